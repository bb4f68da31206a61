"""Lattices of interlocked rings on one engine, checked against :mod:`ringchain.theory`.

The numerical half of the paper (Sec. III.B) and what goes beyond it.  Every lattice is a
:class:`Network` of sites and links, each link with a contact law (:mod:`.laws`), integrated by
one engine (:mod:`.integrate`): a new capability is a new law or a new way to lay out sites.

The floors, top to bottom (each module imports only the floors below it; no cycle, no
underscore name reached across modules):

1. the command line: ``cli``, ``fit_cli``, ``ensemble_cli``, ``sheet_cli``, ``_cli_options`` -- parse, call one
   public function, print;
2. jobs: ``paper``, ``experiment``, ``sweep``, ``ensemble``, ``fit``, ``fit_dynamic``, ``junction``,
   ``effective_mass``, ``contact_bem``, ``dissipation`` -- the paper's tables and figures, a drop read at two
   sensors, grids, ensembles of disordered chains, inverse problems, the impedance experiment,
   the effective mass, the numerical contact at any angle, where the energy of a yielding chain goes;
3. layouts: ``chain``, ``chain_kinds``, ``chain_file``, ``disorder``, ``yielding``, ``ring_chain``, ``ring_beam``,
   ``sheet``, ``sheet_runs`` -- a Chain builds a Network; graded, alternating and joined chains; chain files;
   random rings about a nominal one; contacts that yield; the ring-resolved chain (its own dynamics) and the
   ring as a curved beam; sheets of interlinked rings in two dimensions and their runs;
4. the engine: ``integrate``, ``kernels``, ``results``, ``traces``, ``plots``, ``executors``, ``signals``,
   ``rings_contact``, ``rings_kernels`` -- the integrator layer and its compiled kernels, result records,
   measurement files, figures, where sweeps run, reading pulses; the contacts of rigid tori in space;
5. ``network``, ``laws`` -- sites and links; contact laws with one contract.

What each module owns:

- :mod:`.laws` -- :class:`~.laws.PowerLaw` (Eq. (4), the paper's gamma inside its bracket, Eq. (7)),
  :func:`~.laws.Hertz` (Eq. (1)), :class:`~.laws.LinearSpring` (Eq. (2)), :class:`~.laws.Dashpot`: force,
  stored energy, tangent stiffness, dissipated power from the extension and its rate; beyond the paper
  :class:`~.laws.Thornton` (a contact that yields, with memory), :class:`~.laws.HuntCrossley` and
  :func:`~.laws.loss_factor_spring`;
- :mod:`.network` -- :class:`Network`, :class:`Links`: sites (mass, weight, 1-3 components) and
  links; the dynamics contract every integrator calls (stepper, first-order right-hand side and its
  bandwidth, energies, tolerance scales, fastest frequency), with a fast path for chains;
  :meth:`Network.stack` puts several networks of one layout into one batch;
- :mod:`.integrate` -- :func:`simulate`, :func:`simulate_batch`, :func:`estimate_run`: the model
  contract (``dynamics()``, ``impact_state``, ``recorded``, ``result``), the methods (the compiled
  "dopri5", the default, and "verlet"; SciPy's odeint and solve_ivp as the reference), chunking, the
  energy watch, run estimates; :mod:`.kernels` -- the compiled right-hand sides, Dormand-Prince 5(4)
  and Verlet loops (Numba, cached on disk), laws with memory updated on accepted steps;
- :mod:`.results` -- :class:`NetworkSimulation` (``link_force``), :class:`Simulation` (a chain's run:
  ``contact_force``, ``sensor_force``, the sensor helpers), :class:`EnergyBudget`;
- :mod:`.traces` -- :func:`write_traces` beside :func:`read_traces`, and the other measurement files;
- :mod:`.chain` -- :class:`Chain`: the power-law (Eq. (7)) and dual-spring (Eqs. (5)-(6)) chains,
  uniform or changing along their length, hanging or free; their drop protocol and striker;
  ``Chain.network()``; :mod:`.chain_kinds` builds the graded, alternating and joined chains;
  :mod:`.chain_file` reads chains in TOML; :mod:`.disorder` draws the rings of
  :meth:`Chain.disordered` (seeds, spreads, truncation);
- :mod:`.sheet` -- :class:`Sheet`: square (4-in-1) and triangular (6-in-1) sheets and any layout of
  rings in a plane, hanging under gravity or pretensioned, the contact law of a ring pair at any angle;
  :mod:`.sheet_runs` -- :class:`SheetSimulation` (``link_force``, fields in NetCDF), :func:`read_sheet_run`;
- :mod:`.rings_contact` -- :func:`torus_contacts` (every contact of two tori in any pose: gap, point, normal,
  curvatures), :func:`candidate_pairs` (the broad phase), :func:`linking_number`; :mod:`.rings_kernels` -- the
  same search, cold and warm-started, and the force at a contact (Hertz of the local curvatures or the power
  law of Eq. (4), dashpot, regularised Coulomb friction), compiled;
- :mod:`.ring_beam`, :mod:`.ring_chain` -- :class:`RingModel`, :class:`ReducedRing` (a ring as an
  elastic curved beam) and :class:`RingChain` (a chain of them), :func:`simulate_rings`;
- :mod:`.experiment` -- :func:`~.experiment.run_experiment`: a drop read at two sensors (``ringchain
  simulate``); :mod:`.paper` -- :func:`paper_chain`, :func:`paper_experiment`, the paper's tables
  and figures (``ringchain paper``); :mod:`.sweep` -- :func:`sweep` over grids and chain files through
  any executor; :mod:`.ensemble` -- :func:`ensemble` of disordered chains, read at every ring
  (``ringchain ensemble``); :mod:`.fit`, :mod:`.fit_dynamic` -- :func:`fit_static`, :func:`fit_speed_amplitude`,
  :func:`fit_speed_rings`, :func:`fit_traces`; :mod:`.contact_bem` -- :func:`contact_curve`, :func:`angle_power_law`;
  :mod:`.effective_mass` -- :func:`predict_effective_mass`; :mod:`.junction` -- the small pulse at a
  junction; :mod:`.signals` -- peaks, arrivals, time of flight, widths, spectra.
"""

from ringchain.theory import STANDARD_GRAVITY

from . import laws, signals
from .chain import MODELS, STRIKERS, SUPPORTS, Chain, initial_state
from .contact_angle import AngleContact, AnglePowerLaw, angle_power_law, contact_at_angle
from .contact_bem import HALF_SPACE_LIMIT, ContactCurve, HalfSpaceWarning, PressureMaps, contact_curve
from .disorder import DisorderWarning, draw_rings
from .dissipation import energy_shares, equivalent_contact_dashpot, second_impact
from .effective_mass import fit_effective_mass, predict_effective_mass
from .ensemble import Ensemble, Summary, ensemble, summarize
from .fit import FitError, FitResult, fit_speed_amplitude, fit_speed_rings, fit_static
from .fit_dynamic import TraceRecord, fit_traces
from .integrate import (
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
from .laws import linear_spring_force, power_law_force
from .network import ANCHOR, Links, Network
from .paper import STIFFNESS_SOURCES, PaperExperiment, paper_chain, paper_experiment
from .results import BatchSimulation, EnergyBudget, NetworkBatch, NetworkSimulation, Simulation
from .ring_beam import ReducedRing, RingModel
from .ring_chain import RingChain, RingSimulation, simulate_rings
from .rings import Rings, RingsBatch, RingsEnergy, RingsSimulation
from .rings_contact import CONTACT_FIELDS, TorusContacts, candidate_pairs, linking_number, torus_contacts  # issue 29
from .sheet import Sheet
from .sheet_runs import SheetBatch, SheetSimulation, read_sheet_run
from .signals import NoPulseError, PulseError, TruncatedPulseError, UnresolvedPulseError
from .sweep import Point, sweep, write_csv
from .traces import DataError, read_speed_amplitude, read_static, read_traces, write_traces

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
    # issue 29: rings in space (contacts of two tori in any pose)
    "torus_contacts",
    "TorusContacts",
    "CONTACT_FIELDS",
    "candidate_pairs",
    "linking_number",
]
