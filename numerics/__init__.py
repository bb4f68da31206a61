"""Lattices of interlocked rings on one engine, checked against :mod:`ringchain.theory`.

The numerical half of the paper (Sec. III.B) and what goes beyond it.  Every lattice is a network of
sites and links, each link with a contact law, integrated by one engine: a new capability is a new law
or a new layout, never a new integrator.  The folders are the floors, top to bottom; each imports only
from itself and the floors below (no cycle, no underscore name reached across modules; checked by
tests/test_architecture.py):

- ``cli/`` -- the ``ringchain`` command: parse, call one public function, print;
- ``jobs/`` -- the paper's tables and figures, a drop read at two sensors, sweeps, ensembles, fits;
- ``layouts/`` -- networks built from rings: chains, ring-resolved chains, sheets, disorder, yielding;
- ``contact/`` -- the numerical contact of two tori at any angle;
- ``engine/`` -- network and laws, the integrator layer and its compiled kernels, results, files,
  signals, executors.

This face re-exports every public name, so ``from ringchain.numerics import simulate`` never depends on
where a name lives; ``ringchain.numerics.laws`` and ``ringchain.numerics.signals`` are the engine's
modules under their public names.
"""

import sys

from ringchain.theory import STANDARD_GRAVITY

from .contact.angle import AngleContact, AnglePowerLaw, angle_power_law, contact_at_angle
from .contact.bem import HALF_SPACE_LIMIT, ContactCurve, HalfSpaceWarning, PressureMaps, contact_curve
from .engine import laws, signals
from .engine.integrate import (
    ADAPTIVE_METHODS,
    DEFAULT_METHOD,
    DEFAULT_RTOL,
    METHODS,
    VERLET_STEPS_PER_PERIOD,
    IntegrationError,
    RunEstimate,
    RunTooLargeError,
    estimate_run,
    simulate,
    simulate_batch,
)
from .engine.laws import linear_spring_force, power_law_force
from .engine.network import ANCHOR, Links, Network
from .engine.results import BatchSimulation, EnergyBudget, NetworkBatch, NetworkSimulation, Simulation
from .engine.signals import NoPulseError, PulseError, TruncatedPulseError, UnresolvedPulseError
from .engine.traces import DataError, read_speed_amplitude, read_static, read_traces, write_traces
from .jobs.dissipation import energy_shares, equivalent_contact_dashpot, second_impact
from .jobs.effective_mass import fit_effective_mass, predict_effective_mass
from .jobs.ensemble import Ensemble, Summary, ensemble, summarize
from .jobs.fit import FitError, FitResult, fit_speed_amplitude, fit_speed_rings, fit_static
from .jobs.fit_dynamic import TraceRecord, fit_traces
from .jobs.paper import STIFFNESS_SOURCES, PaperExperiment, paper_chain, paper_experiment
from .jobs.sweep import Point, sweep, write_csv
from .layouts.chain import MODELS, STRIKERS, SUPPORTS, Chain, initial_state
from .layouts.disorder import DisorderWarning, draw_rings
from .layouts.ring_beam import ReducedRing, RingModel
from .layouts.ring_chain import RingChain, RingSimulation, simulate_rings
from .layouts.sheet import Sheet
from .layouts.sheet_runs import SheetBatch, SheetSimulation, read_sheet_run

# The engine's laws and signals under their public module names (one module, two names: an import of
# ringchain.numerics.laws finds it here after the package is imported, and objects compare equal).
sys.modules[f"{__name__}.laws"] = laws
sys.modules[f"{__name__}.signals"] = signals

__all__ = [
    "Chain",
    "MODELS",
    "SUPPORTS",
    "STIFFNESS_SOURCES",
    "Network",
    "Links",
    "ANCHOR",
    "laws",
    "energy_shares",
    "equivalent_contact_dashpot",
    "second_impact",
    "NetworkSimulation",
    "NetworkBatch",
    "STRIKERS",
    "METHODS",
    "paper_chain",
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
    "write_traces",
    "TraceRecord",
    "read_static",
    "read_speed_amplitude",
    "fit_static",
    "fit_speed_amplitude",
    "fit_speed_rings",
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
    "ensemble",
    "Ensemble",
    "Summary",
    "summarize",
    "draw_rings",
    "DisorderWarning",
    "Sheet",
    "SheetSimulation",
    "SheetBatch",
    "read_sheet_run",
]
