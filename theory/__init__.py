"""Theory of chains of interlocked rings: SymPy derivations and the numeric functions made from them.

Importing this package is cheap: it does not import SymPy.  Each numeric function
runs its derivation on first use (or loads the generated code from the disk cache,
see :mod:`ringchain.theory._codegen`).

Static theory of one contact (paper Sec. II, Eqs. 1-4, App. A):

- :func:`hertz_stiffness` -- K_c of two tori, circular or elliptical contact (Eq. 1);
- :func:`bending_stiffness` -- K_b of one ring by Castigliano (Eq. 2);
- :func:`series_displacement`, :func:`local_exponent`, :func:`crossover_force`,
  :func:`fit_power_law` -- the series law and its power-law reduction (Eqs. 3-4);
- :class:`Ring`, :class:`Material` -- a ring of the chain and its material.

Long waves (paper Sec. IV.C, App. B; modules :mod:`.longwave` and :mod:`.solitary`):

- :func:`solitary_wave_speed`, :func:`solitary_wave_speed_from_velocity` -- V_s of the
  compact solitary wave (Eq. vsfm);
- :func:`solitary_wave_width`, :func:`solitary_wave_profile` -- its support and force profile;
- :func:`solitary_wave_speed_prestressed`, :func:`linear_sound_speed` -- the wave on a chain
  pre-stretched by a static force (beyond the paper) and its small-amplitude limit.

The paper's reported numbers (Tables I-II, FE exponents) are data in :mod:`.paper_data`.
"""

from . import paper_data
from .contact import contact_ellipse, hertz_stiffness, minimum_contact_angle
from .geometry import MIN_CHAIN_ASPECT_RATIO, PAPER_TUBE_RADIUS, Ring
from .longwave import linear_sound_speed
from .materials import MATERIALS, STAINLESS_STEEL_304, Material, get_material
from .ring import bending_stiffness
from .series import (
    DEFAULT_FORCE_WINDOW,
    crossover_force,
    fit_power_law,
    local_exponent,
    n_per_mm_to_si,
    series_displacement,
    si_to_n_per_mm,
)
from .solitary import (
    solitary_wave_profile,
    solitary_wave_speed,
    solitary_wave_speed_from_velocity,
    solitary_wave_speed_prestressed,
    solitary_wave_width,
)

__all__ = [
    "paper_data",
    "hertz_stiffness",
    "contact_ellipse",
    "minimum_contact_angle",
    "bending_stiffness",
    "series_displacement",
    "local_exponent",
    "crossover_force",
    "fit_power_law",
    "n_per_mm_to_si",
    "si_to_n_per_mm",
    "DEFAULT_FORCE_WINDOW",
    "Ring",
    "MIN_CHAIN_ASPECT_RATIO",
    "PAPER_TUBE_RADIUS",
    "Material",
    "MATERIALS",
    "STAINLESS_STEEL_304",
    "get_material",
    "solitary_wave_speed",
    "solitary_wave_speed_from_velocity",
    "solitary_wave_width",
    "solitary_wave_profile",
    "solitary_wave_speed_prestressed",
    "linear_sound_speed",
]
