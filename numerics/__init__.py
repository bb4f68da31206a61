"""Lattice models of chains of interlocked rings, checked against :mod:`ringchain.theory`.

The numerical half of the paper (Sec. III.B): the chain integrated ring by ring.

- :class:`Chain` -- the power-law chain (Eq. (7)) or the dual-spring chain
  (Eqs. (5)-(6)), built from K, n, m, a or from a :class:`~ringchain.theory.Ring`,
  hanging from a fixed support under gravity or free; beyond the paper, a chain that changes
  along its length (per-ring and per-contact arrays; :meth:`Chain.from_rings`, :meth:`Chain.graded`,
  :meth:`Chain.alternating`, :meth:`Chain.joined`; TOML descriptions in :mod:`.chain_file`);
- :func:`simulate`, :func:`simulate_batch` -- an impact or a drop on ring 0, integrated
  with :func:`scipy.integrate.solve_ivp` or fixed-step velocity Verlet; a batch of runs
  is one vectorised array problem; ``initial=(x0, u0)`` starts from any other state;
- :class:`Simulation` -- contact, sensor and support forces, energy budget, CSV;
  :func:`estimate_run` -- memory and work of a run before it starts;
- :mod:`~ringchain.numerics.signals` -- peak arrival, time of flight, wave speed, width,
  the tail after the pulse and its spectrum;
- :func:`contact_curve` -- numerical contact of two tori at any angle, one patch or two
  (boundary elements on the exact gap, :mod:`~ringchain.numerics.contact_bem`);
- :func:`paper_experiment` -- the paper's 20-ring drop experiment read at rings 6 and 12
  (:mod:`~ringchain.numerics.paper`, with the paper's tables and figures);
- :class:`RingModel`, :class:`RingChain`, :func:`simulate_rings` -- beyond the paper: each ring an
  elastic curved beam (its modes, its diametral stiffness, a Craig-Bampton reduction) and the chain
  of such rings joined by Hertz contacts; :func:`predict_effective_mass` fits the power-law lattice's
  m_eff/m0 to it (modules :mod:`.ring_beam`, :mod:`.effective_mass`);
- :func:`sweep` -- a parameter grid through any :class:`concurrent.futures.Executor`
  (local processes, or a Dask cluster's ``client.get_executor()``), one row per point;
  the module itself is ``importlib.import_module("ringchain.numerics.sweep")``;
- :mod:`~ringchain.numerics.fit` -- from measurements to parameters: :func:`read_traces`,
  :func:`read_static`, :func:`fit_static` (K and n, Eqs. 3-4), :func:`fit_speed_amplitude`
  (m_eff/m0 through Eq. (8)), :func:`fit_traces` (m, dashpots, K, n from sensor traces).
"""

from . import signals
from .chain import MODELS, STIFFNESS_SOURCES, SUPPORTS, Chain
from .contact_bem import (
    HALF_SPACE_LIMIT,
    AngleContact,
    AnglePowerLaw,
    ContactCurve,
    HalfSpaceWarning,
    PressureMaps,
    angle_power_law,
    contact_at_angle,
    contact_curve,
)
from .effective_mass import fit_effective_mass, predict_effective_mass
from .fit import (
    DataError,
    FitError,
    FitResult,
    fit_speed_amplitude,
    fit_static,
    fit_traces,
    read_speed_amplitude,
    read_static,
    read_traces,
)
from .models import STANDARD_GRAVITY, Lattice, linear_spring_force, power_law_force
from .paper import PaperExperiment, paper_experiment
from .ring_beam import ReducedRing, RingChain, RingModel, RingSimulation, simulate_rings
from .signals import NoPulseError, PulseError, TruncatedPulseError, UnresolvedPulseError
from .solve import (
    ADAPTIVE_METHODS,
    DEFAULT_METHOD,
    DEFAULT_RTOL,
    VERLET_STEPS_PER_PERIOD,
    BatchSimulation,
    EnergyBudget,
    IntegrationError,
    RunEstimate,
    RunTooLargeError,
    Simulation,
    estimate_run,
    initial_state,
    simulate,
    simulate_batch,
)
from .sweep import Point, sweep, write_csv

__all__ = [
    "Chain",
    "MODELS",
    "SUPPORTS",
    "STIFFNESS_SOURCES",
    "Lattice",
    "power_law_force",
    "linear_spring_force",
    "STANDARD_GRAVITY",
    "simulate",
    "simulate_batch",
    "estimate_run",
    "initial_state",
    "Simulation",
    "BatchSimulation",
    "EnergyBudget",
    "RunEstimate",
    "paper_experiment",
    "PaperExperiment",
    "ADAPTIVE_METHODS",
    "DEFAULT_METHOD",
    "DEFAULT_RTOL",
    "VERLET_STEPS_PER_PERIOD",
    "IntegrationError",
    "RunTooLargeError",
    "PulseError",
    "NoPulseError",
    "TruncatedPulseError",
    "UnresolvedPulseError",
    "signals",
    "sweep",
    "Point",
    "write_csv",
    "contact_curve",
    "ContactCurve",
    "PressureMaps",
    "HalfSpaceWarning",
    "angle_power_law",
    "AnglePowerLaw",
    "contact_at_angle",
    "AngleContact",
    "HALF_SPACE_LIMIT",
    "read_traces",
    "read_static",
    "read_speed_amplitude",
    "fit_static",
    "fit_speed_amplitude",
    "fit_traces",
    "FitResult",
    "FitError",
    "DataError",
    "RingModel",
    "ReducedRing",
    "RingChain",
    "RingSimulation",
    "simulate_rings",
    "predict_effective_mass",
    "fit_effective_mass",
]
