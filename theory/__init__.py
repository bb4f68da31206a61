"""Theory of chains of interlocked rings: SymPy derivations and the numeric functions made from them.

Importing this package is cheap: it does not import SymPy.  Each numeric function
runs its derivation on first use (or loads the generated code from the disk cache,
see :mod:`ringchain.theory._codegen`).

Static theory of one contact (paper Sec. II, Eqs. 1-4, App. A):

- :func:`hertz_stiffness` -- K_c of two tori, circular or elliptical contact (Eq. 1);
- :func:`hertz_stiffness_pair` -- K_c of two different tori (radii, materials), for chains that vary;
- :func:`contact_semi_axes` -- the semi-axes of the contact ellipse under a force (where it outgrows the tube);
- :func:`torus_gap`, :func:`contact_patches` -- the exact gap of two tori beyond its quadratic
  (Hertz) part, and the two contact points it has below theta_min (:mod:`.gap`);
- :func:`bending_stiffness` -- K_b of one ring by Castigliano (Eq. 2);
- :func:`series_displacement`, :func:`local_exponent`, :func:`crossover_force`,
  :func:`fit_power_law` -- the series law and its power-law reduction (Eqs. 3-4);
- :class:`Ring`, :class:`Material` -- a ring of the chain and its material.

Long waves (paper Sec. IV.C, App. B; modules :mod:`.longwave`, :mod:`.solitary` and :mod:`.prestressed`):

- :func:`solitary_wave_speed`, :func:`solitary_wave_speed_from_velocity` -- V_s of the
  compact solitary wave (Eq. (8));
- :func:`solitary_wave_width`, :func:`solitary_wave_profile` -- its support and force profile;
- :func:`solitary_wave_speed_prestressed`, :func:`linear_sound_speed` -- the wave on a chain
  pre-stretched by a static force (beyond the paper) and its small-amplitude limit.

Linear waves and what the pulse carries (beyond the paper; modules :mod:`.linear` and :mod:`.pulse`):

- :func:`dispersion`, :func:`band_edges`, :func:`sound_speed` -- both lattice models linearised
  about a static force: branches, band edges (where the trailing oscillations sit), long-wave speed;
- :func:`linear_travel_time` -- a small pulse through the hanging chain, whose weight grades the speed;
- :func:`impedance`, :func:`junction_coefficients` -- a long wave meeting the junction of two chains:
  reflected and transmitted force from the two impedances;
- :func:`solitary_wave_energy`, :func:`solitary_wave_momentum` -- invariants of the compact wave;
- :func:`impact_speed` -- sqrt(2 g h), the speed of a dropped ring when its slack is taken up;
- :func:`impact_amplitude` -- the peak force launched by a striker at speed v0 (F_m ~ v0^(2n/(n+1))).

Disorder: rings that differ from one another (beyond the paper; modules :mod:`.disorder`, :mod:`.scattering`
and :mod:`.attenuation`):

- :func:`effective_medium_speed`, :func:`harmonic_mean_speed` -- long linear waves: the homogenised
  speed <a>/sqrt(<m><1/k>) and the harmonic mean of the local speeds, from per-ring arrays;
- :func:`disordered_solitary_wave_speed`, :func:`disorder_speed_shift` -- the compact wave's mean speed
  over a disordered chain, and both speeds' shift to second order in the spreads;
- :func:`impedance_spread`, :func:`chain_impedance_spread` -- the spread of ln sqrt(m k) that scatters;
- :func:`localization_length`, :func:`disorder_pulse_spread` -- linear waves: energy decay of a harmonic
  wave, Gaussian spreading of a long pulse (O'Doherty-Anstey);
- :func:`disorder_attenuation_length`, :func:`attenuated_travel_time` -- the compact wave's loss of
  peak force, and the slowing that comes with it.

Rings that bend (beyond the paper; module :mod:`.curved_beam`):

- :func:`ring_frequencies`, :func:`inextensional_frequency` -- natural frequencies of a free ring as
  a thick curved beam, and the classical thin-ring ones (Hoppe in plane, Michell out of plane);
  the exact curved elements of :class:`ringchain.numerics.RingModel` come from the same module.

Sheets of interlinked rings (beyond the paper, its Sec. V outlook; module :mod:`.sheet`):

- :func:`sheet_dispersion` -- the in-plane branches of a pretensioned square (4-in-1) or triangular
  (6-in-1) sheet, from the network's energy to second order (axial stiffness k, geometric stiffness T/a);
- :func:`sheet_group_velocity` -- the group velocity of each branch, grad_q omega (the front of a point source);
- :func:`sheet_sound_speeds`, :class:`SheetSpeeds` -- its long-wave longitudinal and transverse speeds
  against the direction (anisotropic for the square sheet, isotropic for the triangular one).

Contacts that yield (beyond the paper; modules :mod:`.subsurface` and :mod:`.plastic`):

- :func:`subsurface_stress`, :func:`first_yield`, :func:`yield_force` -- the stresses below the Hertz
  contact of two tori and the force at which it first yields (von Mises, p0 = 1.60 Y at nu = 0.29);
- :func:`thornton_loading_force`, :func:`thornton_unloading_force`, :func:`thornton_residual_indentation`,
  :func:`thornton_energy`, :func:`plastic_stiffness`, :func:`equivalent_radius` -- Thornton's
  elastic-perfectly plastic contact law with memory of the largest approach;
- :func:`yield_velocity`, :func:`restitution_coefficient` -- two colliding rings: the speed at which the
  contact yields, and the coefficient of restitution beyond it;
- :data:`STAINLESS_STEEL_304_ANNEALED`, :data:`STAINLESS_STEEL_304_COLD_WORKED` -- materials with a yield strength.

The paper's reported numbers (Tables I-II, FE exponents) are data in :mod:`.paper_data`.

One convention for every signature: the quantity a function is evaluated at comes first and may be
given by position (a force ``F``, ``F_m`` or ``F_0``, a speed ``v0``, a wavenumber ``q``, a position
``x``); the geometry and material of a contact (``R, r, E, nu, angle``) follow by position, since
every swap among them is refused; the parameters of the chain and of its contact law are
keyword-only, in the one order ``F_0, K, n, m, a, K_c, K_b``::

    F_m = impact_amplitude(v0, K=K, n=n, m=m, a=a)
    V_s = solitary_wave_speed(F_m, K=K, n=n, m=m, a=a)
    c_0 = sound_speed(F_0, model="power-law", K=K, n=n, m=m, a=a)

A static contact force is spelled ``F_0`` everywhere.  Parameters outside that order are keyword-only
too, placed by what they are (each module's docstring says where): Thornton's memory ``delta_max`` and
constant ``delta_y`` after ``K_c``; the yield strength ``Y`` after the contact's ``angle``; a sheet's link
tension ``T`` where ``F_0`` stands and its stiffness ``k`` where ``K`` stands; the spreads of a disordered
chain (``sigma_K``, ``sigma_m``, ``correlation``, ``sigma_Z``) after the chain's parameters::

    F_y = first_yield(R, r, E, nu, angle, Y=Y).force
    F = thornton_unloading_force(delta, delta_max=d_max, K_c=K_c, delta_y=d_y)
    c = effective_medium_speed(k=k, m=m, a=a)
"""

from . import curved_beam, paper_data
from .attenuation import attenuated_travel_time, disorder_attenuation_length  # issue 23: disorder
from .contact import (
    contact_ellipse,
    contact_modulus,
    contact_semi_axes,
    hertz_stiffness,
    hertz_stiffness_pair,
    minimum_contact_angle,
)
from .curved_beam import inextensional_frequency, ring_frequencies
from .disorder import (  # issue 23: disorder
    disorder_speed_shift,
    disordered_solitary_wave_speed,
    effective_medium_speed,
    harmonic_mean_speed,
)
from .gap import contact_patches, smallest_patch_angle, torus_gap
from .geometry import MIN_CHAIN_ASPECT_RATIO, PAPER_TUBE_RADIUS, Ring
from .linear import (
    STANDARD_GRAVITY,
    BandEdges,
    band_edges,
    dispersion,
    impact_speed,
    impedance,
    junction_coefficients,
    linear_travel_time,
    sound_speed,
)
from .longwave import linear_sound_speed
from .materials import (
    MATERIALS,
    STAINLESS_STEEL_304,
    STAINLESS_STEEL_304_ANNEALED,
    STAINLESS_STEEL_304_COLD_WORKED,
    Material,
    get_material,
)
from .plastic import (
    equivalent_radius,
    plastic_stiffness,
    restitution_coefficient,
    thornton_energy,
    thornton_loading_force,
    thornton_residual_indentation,
    thornton_unloading_force,
    yield_velocity,
)
from .prestressed import solitary_wave_speed_prestressed
from .pulse import impact_amplitude, solitary_wave_energy, solitary_wave_momentum
from .ring import bending_stiffness
from .scattering import (  # issue 23: disorder
    chain_impedance_spread,
    disorder_pulse_spread,
    impedance_spread,
    localization_length,
)
from .series import (
    DEFAULT_FORCE_WINDOW,
    crossover_force,
    fit_power_law,
    fit_power_law_to_curve,
    local_exponent,
    n_per_mm_to_si,
    series_displacement,
    series_extension,
    series_stiffness_for_power_law,
    si_to_n_per_mm,
)
from .sheet import SheetSpeeds, sheet_dispersion, sheet_group_velocity, sheet_sound_speeds
from .solitary import (
    solitary_wave_profile,
    solitary_wave_speed,
    solitary_wave_speed_from_velocity,
    solitary_wave_width,
)
from .subsurface import FirstYield, first_yield, subsurface_stress, yield_force

__all__ = [
    "paper_data",
    "hertz_stiffness",
    "hertz_stiffness_pair",
    "contact_ellipse",
    "contact_semi_axes",
    "minimum_contact_angle",
    "contact_patches",
    "smallest_patch_angle",
    "torus_gap",
    "contact_modulus",
    "bending_stiffness",
    "series_displacement",
    "local_exponent",
    "crossover_force",
    "fit_power_law",
    "fit_power_law_to_curve",
    "series_extension",
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
    "dispersion",
    "band_edges",
    "BandEdges",
    "sound_speed",
    "linear_travel_time",
    "impedance",
    "junction_coefficients",
    "impact_speed",
    "STANDARD_GRAVITY",
    "series_stiffness_for_power_law",
    "solitary_wave_energy",
    "solitary_wave_momentum",
    "impact_amplitude",
    # issue 23: disorder
    "effective_medium_speed",
    "harmonic_mean_speed",
    "disordered_solitary_wave_speed",
    "disorder_speed_shift",
    "impedance_spread",
    "chain_impedance_spread",
    "localization_length",
    "disorder_pulse_spread",
    "disorder_attenuation_length",
    "attenuated_travel_time",
    "curved_beam",
    "ring_frequencies",
    "inextensional_frequency",
    "sheet_dispersion",
    "sheet_group_velocity",
    "sheet_sound_speeds",
    "SheetSpeeds",
    # issue 22: contacts that yield
    "subsurface_stress",
    "first_yield",
    "FirstYield",
    "yield_force",
    "thornton_loading_force",
    "thornton_unloading_force",
    "thornton_residual_indentation",
    "thornton_energy",
    "plastic_stiffness",
    "equivalent_radius",
    "yield_velocity",
    "restitution_coefficient",
    "STAINLESS_STEEL_304_ANNEALED",
    "STAINLESS_STEEL_304_COLD_WORKED",
]
