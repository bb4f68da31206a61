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
modules under their public names.  A name's module is imported when the name is first read (``_WHERE``
below): importing the package costs NumPy and the theory's face, not Numba, SciPy or Matplotlib.
"""

import importlib
import sys

from .engine import laws, signals

#: Where each public name lives, relative to this package (or absolute).  The names are imported on first
#: use (PEP 562: :func:`__getattr__` below), so that ``import ringchain.numerics`` loads neither Numba and the
#: compiled kernels nor SciPy, Matplotlib or SymPy, and a command imports only what it runs.
_WHERE = {
    "ringchain.theory": ("STANDARD_GRAVITY",),
    ".contact.angle": ("AngleContact", "AnglePowerLaw", "angle_power_law", "contact_at_angle"),
    ".contact.bem": ("HALF_SPACE_LIMIT", "ContactCurve", "HalfSpaceWarning", "PressureMaps", "contact_curve"),
    ".contact.tori": ("CONTACT_FIELDS", "TorusContacts", "candidate_pairs", "linking_number", "torus_contacts"),
    ".engine.integrate": (
        "ADAPTIVE_METHODS",
        "DEFAULT_METHOD",
        "DEFAULT_RTOL",
        "METHODS",
        "VERLET_STEPS_PER_PERIOD",
        "IntegrationError",
        "RunEstimate",
        "RunTooLargeError",
        "estimate_run",
        "simulate",
        "simulate_batch",
    ),
    ".engine.laws": ("linear_spring_force", "power_law_force"),
    ".engine.network": ("ANCHOR", "Links", "Network"),
    ".engine.results": ("BatchSimulation", "EnergyBudget", "NetworkBatch", "NetworkSimulation", "Simulation"),
    ".engine.signals": ("NoPulseError", "PulseError", "TruncatedPulseError", "UnresolvedPulseError"),
    ".engine.traces": ("DataError", "read_speed_amplitude", "read_static", "read_traces", "write_traces"),
    ".jobs.dissipation": ("energy_shares", "equivalent_contact_dashpot", "second_impact"),
    ".jobs.effective_mass": ("fit_effective_mass", "predict_effective_mass"),
    ".jobs.ensemble": ("Ensemble", "Summary", "ensemble", "summarize"),
    ".jobs.fit": ("FitError", "FitResult", "fit_speed_amplitude", "fit_speed_lattice", "fit_speed_rings", "fit_static"),
    ".jobs.fit_dynamic": ("TraceRecord", "fit_traces"),
    ".jobs.paper": ("STIFFNESS_SOURCES", "PaperExperiment", "paper_chain", "paper_experiment"),
    ".jobs.sweep": ("Point", "sweep", "write_csv"),
    ".layouts.chain": ("MODELS", "STRIKERS", "SUPPORTS", "Chain", "initial_state"),
    ".layouts.disorder": ("DisorderWarning", "draw_rings"),
    ".layouts.ring_beam": ("ReducedRing", "RingModel"),
    ".layouts.ring_chain": ("RingChain", "RingSimulation", "simulate_rings"),
    ".layouts.rings": ("Rings", "RingsBatch", "RingsEnergy", "RingsSimulation"),
    ".layouts.sheet": ("Sheet",),
    ".layouts.sheet_runs": ("SheetBatch", "SheetSimulation", "read_sheet_run", "sheet_run_options"),
}
_OWNER = {name: module for module, names in _WHERE.items() for name in names}


def __getattr__(name: str):
    """A public name read for the first time: import its module, keep the value here (the next read is an
    ordinary attribute).  ``from ringchain.numerics import Chain``, ``numerics.Chain`` and ``import *`` (through
    ``__all__``) work as with imports at the top."""
    module = _OWNER.get(name)
    if module is None:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    value = globals()[name] = getattr(importlib.import_module(module, __name__), name)
    return value


def __dir__():
    return sorted({*globals(), *_OWNER})


# The engine's laws and signals under their public module names (one module, two names: an import of
# ringchain.numerics.laws finds it here after the package is imported, and objects compare equal).
sys.modules[f"{__name__}.laws"] = laws
sys.modules[f"{__name__}.signals"] = signals

__all__ = [
    "Chain",
    "Rings",
    "RingsSimulation",
    "RingsBatch",
    "RingsEnergy",
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
    "fit_speed_lattice",
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
    "sheet_run_options",
    "torus_contacts",
    "TorusContacts",
    "CONTACT_FIELDS",
    "candidate_pairs",
    "linking_number",
]
