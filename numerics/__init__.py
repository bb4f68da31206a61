"""Lattice models of chains of interlocked rings, checked against :mod:`ringchain.theory`.

The numerical half of the paper (Sec. III.B): the chain integrated ring by ring.

- :class:`Chain` -- the power-law chain (Eq. power law) or the dual-spring chain
  (Eq. dual-spring), built from K, n, m, a or from a :class:`~ringchain.theory.Ring`,
  hanging from a fixed support under gravity or free;
- :func:`simulate`, :func:`simulate_batch` -- an impact or a drop on ring 0, integrated
  with :func:`scipy.integrate.solve_ivp` or fixed-step velocity Verlet; a batch of runs
  is one vectorised array problem;
- :class:`Simulation` -- contact, sensor and support forces, energy budget, CSV;
- :mod:`~ringchain.numerics.signals` -- peak arrival, time of flight, wave speed, width;
- :func:`paper_experiment` -- the paper's 20-ring drop experiment read at rings 6 and 12;
- :func:`sweep` -- a parameter grid through any :class:`concurrent.futures.Executor`
  (local processes, or a Dask cluster's ``client.get_executor()``), one row per point;
  the module itself is ``importlib.import_module("ringchain.numerics.sweep")``.
"""

from . import signals
from .chain import MODELS, SUPPORTS, Chain
from .models import STANDARD_GRAVITY, Lattice, linear_spring_force, power_law_force
from .solve import (
    ADAPTIVE_METHODS,
    DEFAULT_METHOD,
    DEFAULT_RTOL,
    VERLET_STEPS_PER_PERIOD,
    BatchSimulation,
    EnergyBudget,
    PaperExperiment,
    Simulation,
    initial_state,
    paper_experiment,
    simulate,
    simulate_batch,
)
from .sweep import Point, sweep, write_csv

__all__ = [
    "Chain",
    "MODELS",
    "SUPPORTS",
    "Lattice",
    "power_law_force",
    "linear_spring_force",
    "STANDARD_GRAVITY",
    "simulate",
    "simulate_batch",
    "initial_state",
    "Simulation",
    "BatchSimulation",
    "EnergyBudget",
    "paper_experiment",
    "PaperExperiment",
    "ADAPTIVE_METHODS",
    "DEFAULT_METHOD",
    "DEFAULT_RTOL",
    "VERLET_STEPS_PER_PERIOD",
    "signals",
    "sweep",
    "Point",
    "write_csv",
]
