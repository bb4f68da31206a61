r"""What a run returns: times, states, and the forces and energies derived from them on demand.

- :class:`EnergyBudget` -- kinetic, contact, bending, gravity and dissipated energy;
- :class:`NetworkSimulation`, :class:`NetworkBatch` -- a run (a batch of runs) of a
  :class:`~ringchain.numerics.Network`: ``link_force`` (time x links), displacements,
  velocities, energy;
- :class:`Simulation`, :class:`BatchSimulation` -- a run (a batch) of a chain
  (:class:`~ringchain.numerics.Chain`): the network run read as the paper reads its chain,
  ``contact_force``, ``sensor_force`` and the sensor helpers of :mod:`~ringchain.numerics.signals`.

A result holds the states of every site, or of the sites a run was asked to record (the
sensors' rings of a long chain); forces are computed from the recorded states when asked for:
for a network in two or three dimensions (a sheet) the link forces and the energies in one
compiled pass over the samples (:mod:`.fields`), for a chain by the network's NumPy slices.
The chain's views go through the chain's own index maps (``contact_links``,
``sensor_links``...), so this module knows nothing of how a chain is laid out.
"""

from __future__ import annotations

import csv
import functools
from dataclasses import dataclass, field

import numpy as np

from . import signals
from ._files import replacing

__all__ = ["EnergyBudget", "NetworkSimulation", "NetworkBatch", "Simulation", "BatchSimulation"]


@dataclass(frozen=True)
class EnergyBudget:
    """Energies of a run, J, each of shape (..., len(t)).

    ``gravity`` is measured from the initial configuration.  Without dashpots,
    ``dissipated`` is zero and ``total`` is conserved; with them, ``total`` (which
    includes the dissipated energy) is conserved and the mechanical energy
    ``total - dissipated`` only decreases.  ``plastic`` is the work done on contacts that
    yield (:class:`~ringchain.numerics.laws.Thornton`), counted from virgin contacts and
    part of ``total``.
    """

    kinetic: np.ndarray
    contact: np.ndarray
    bending: np.ndarray
    gravity: np.ndarray
    dissipated: np.ndarray
    plastic: np.ndarray | float = 0.0

    @property
    def mechanical(self) -> np.ndarray:
        return self.kinetic + self.contact + self.bending + self.gravity

    @property
    def total(self) -> np.ndarray:
        return self.mechanical + self.dissipated + self.plastic


@dataclass(frozen=True, eq=False)
class NetworkSimulation:
    """A run of a network: times ``t`` (s), displacements ``x`` and velocities ``u`` (m, m/s).

    Attributes
    ----------
    t : ndarray, shape (T,)
    x, u : ndarray, shape (..., T, K)
        Coordinates of the recorded sites (all, or :attr:`sites`), ``dim`` per site.
    dissipated : ndarray, shape (..., T)
        Energy the dashpots took out since t = 0, J.
    g : float
        Gravity the run had, m/s^2 (0 without).
    network : Network
    stats : dict
        What the integrator reports (method, right-hand-side evaluations, step).
    sites : ndarray or None
        The sites recorded, sorted (None: every site).
    memory : ndarray or None
        Laws with memory: the memory of every link at each sample, m, shape (..., T, n_links) (the
        largest approach of a :class:`~ringchain.numerics.laws.Thornton` contact); None otherwise.
    """

    t: np.ndarray
    x: np.ndarray
    u: np.ndarray
    dissipated: np.ndarray
    g: float
    network: object = None
    stats: dict = field(default_factory=dict, repr=False)
    sites: np.ndarray | None = None
    memory: np.ndarray | None = None

    @functools.cached_property
    def links(self) -> np.ndarray:
        """Links whose forces :attr:`link_force` holds: every link, or those between recorded sites."""
        net = self.network
        if self.sites is None:
            return np.arange(net.n_links)
        inner = np.isin(net.i, self.sites) & (net.anchored | np.isin(net.j, self.sites))
        return np.flatnonzero(inner)

    @functools.cached_property
    def link_force(self) -> np.ndarray:
        """Force of each link (:attr:`links`), N, positive in tension; shape (..., T, n_links)."""
        if self._fields is not None:
            return self._fields.force
        return self.network.link_forces(self.x, self.u, self.links, self.sites, memory=self.memory)

    @functools.cached_property
    def _fields(self):
        """A network in two or three dimensions (a sheet): its link forces and, with every site recorded, its
        energies, compiled in one pass over the samples (:mod:`.fields`); None otherwise (a chain's NumPy slices)."""
        from . import fields

        if self.network.dim == 1 or not fields.compiles(self.network):  # a chain: NumPy slices, no compile
            return None
        options = dict(links=self.links, sites=self.sites, g=self.g, energies=self.sites is None)
        if self.x.ndim == 2:
            return fields.fields(self.network, self.x, self.u, memory=self.memory, **options)
        runs = [fields.fields(self.network, self.x[b], self.u[b], memory=None if self.memory is None else
                              self.memory[b], member=b if self.network.batch_shape else 0, **options)
                for b in range(self.x.shape[0])]  # fmt: skip
        parts = zip(*runs, strict=True)
        return fields.Fields(*(np.stack(part) if isinstance(part[0], np.ndarray) else part[0] for part in parts))

    def _require_all(self, what: str) -> None:
        if self.sites is not None:
            raise ValueError(f"{what} needs every site, but this run recorded {len(self.sites)} sites only "
                             "(simulate with rings=None to keep them all)")  # fmt: skip

    @property
    def displacement(self) -> np.ndarray:
        """Displacements, m, shape (..., T, sites, dim)."""
        return self.x.reshape(*self.x.shape[:-1], -1, self.network.dim)

    @property
    def velocity(self) -> np.ndarray:
        """Velocities, m/s, shape (..., T, sites, dim)."""
        return self.u.reshape(*self.u.shape[:-1], -1, self.network.dim)

    def energy(self) -> EnergyBudget:
        """Kinetic, contact, bending, gravity and dissipated energy, J (see :class:`EnergyBudget`)."""
        self._require_all("energy")
        if self._fields is not None:
            f = self._fields
            return EnergyBudget(kinetic=f.kinetic, contact=f.contact, bending=f.bending, gravity=f.gravity,
                                dissipated=self.dissipated, plastic=f.plastic)  # fmt: skip
        memory = {} if self.memory is None else {"memory": self.memory}
        return self.network.energy(self.x, self.u, self.x[..., :1, :], self.g, self.dissipated, **memory)


@dataclass(frozen=True, eq=False)
class NetworkBatch(NetworkSimulation):
    """B runs of one network (or one each of a stack): arrays of shape (B, T, ...); ``result[b]`` is run b."""

    def __len__(self) -> int:
        return self.x.shape[0]

    def __getitem__(self, b) -> NetworkSimulation:
        b = range(len(self))[b]
        net = self.network.member(b) if self.network.batch_shape else self.network
        return NetworkSimulation(t=self.t, x=self.x[b], u=self.u[b], dissipated=self.dissipated[b], g=self.g,
                                 network=net, stats=self.stats, sites=self.sites,
                                 memory=None if self.memory is None else self.memory[b])  # fmt: skip


@dataclass(frozen=True, eq=False)
class Simulation(NetworkSimulation):
    """One run of a chain: its network's run, read as the paper reads the chain.

    Forces are derived on demand: ``contact_force`` (T, n_rings - 1), ``sensor_force``
    (T, n_rings), ``bending_force`` and ``support_force``; the sensor helpers read the
    leading pulse of the sensor force of a ring (:mod:`ringchain.numerics.signals`,
    which raises a :class:`~ringchain.numerics.signals.PulseError` when there is no
    complete, resolved pulse to read).  A run that recorded only some ``rings`` has the
    sensor helpers for those rings only.

    Attributes
    ----------
    chain : Chain
    impact_velocity : float or ndarray
        Speed of ring 0 at t = 0, m/s.
    drop_height : float, ndarray or None
        m, for a drop.
    rings : tuple or None
        The rings recorded (None: all).
    """

    chain: object = None
    impact_velocity: np.ndarray | float = 0.0
    drop_height: np.ndarray | float | None = None
    rings: tuple | None = None

    def __post_init__(self):
        if self.network is None and callable(getattr(self.chain, "network", None)):
            object.__setattr__(self, "network", self.chain.network())
        if self.sites is None and self.rings is not None:
            object.__setattr__(self, "sites", self.chain.recorded_sites(self.rings))

    def _require_all(self, what: str) -> None:
        if self.rings is not None:
            raise ValueError(
                f"{what} needs every ring, but this run recorded rings {list(self.rings)} only "
                "(simulate with rings=None to keep them all)"
            )

    def _link_force_of(self, links) -> np.ndarray:
        """Forces of the chain's ``links`` (1-d array), N, shape (..., T, len(links)), from the recorded sites."""
        return self.network.link_forces(self.x, self.u, links, self.sites, memory=self.memory)

    def _sensor(self, rings) -> np.ndarray:
        """Sensor forces of ``rings`` (1-d array), N, shape (..., T, len(rings)); see :attr:`sensor_force`."""
        links, weights = self.chain.sensor_links(rings)
        unique, index = np.unique(links, return_inverse=True)
        forces = self._link_force_of(unique)[..., index.reshape(links.shape)]
        return np.sum(forces * weights, axis=-1)

    @functools.cached_property
    def bond_force(self) -> np.ndarray:
        """Force in every link of the chain's network, N, positive in tension (its :attr:`link_force`)."""
        self._require_all("bond_force")
        return self.link_force

    @functools.cached_property
    def contact_force(self) -> np.ndarray:
        """Force between ring i and ring i+1, N, positive in tension; shape (..., T, n_rings - 1).  Selected from
        :attr:`bond_force` once and kept: a loop that reads one contact at a time copies nothing more."""
        return self.bond_force[..., self.chain.contact_links]

    @property
    def bending_force(self) -> np.ndarray | None:
        """Force through the body of ring i (dual-spring bending spring and dashpot), N."""
        links = self.chain.bending_links
        return None if links is None else self.bond_force[..., links]

    @property
    def support_force(self) -> np.ndarray | None:
        """Force between the top ring and the fixed support, N (None for a free end); a run that recorded
        some rings only has it if it recorded the top ring."""
        k = self.chain.support_link
        if k is None:
            return None
        return self.bond_force[..., k] if self.rings is None else self._link_force_of(np.array([k]))[..., 0]

    @functools.cached_property
    def sensor_force(self) -> np.ndarray:
        """Force read by a sensor embedded in each ring, N; shape (..., T, n_rings).

        The force carried across the middle of the ring body.  In the dual-spring model
        it is the force of the ring's bending spring (with its dashpot), which joins the
        ring's two halves.  In the power-law model a ring is rigid, and Newton's law for
        its lower half (half the mass and half the weight, the ring being symmetric)
        gives exactly the mean of the forces on its two sides: with F_below, F_above the
        contact forces and T the force at mid-ring, (m/2) a = T - F_below - m_g g/2 and
        m a = F_above - F_below - m_g g, so T = (F_below + F_above)/2.  Ring 0 has no
        force below it; the top ring has the support (or nothing) above it.
        """
        self._require_all("sensor_force")
        return self._sensor(np.arange(self.chain.n_rings))

    @property
    def ring_displacement(self) -> np.ndarray:
        """Displacement of the centre of mass of each ring, m; shape (..., T, n_rings)."""
        self._require_all("ring_displacement")
        k = self.chain.sites_per_ring
        return self.x.reshape(*self.x.shape[:-1], -1, k).mean(axis=-1)

    @property
    def ring_velocity(self) -> np.ndarray:
        """Velocity of the centre of mass of each ring, m/s; shape (..., T, n_rings)."""
        self._require_all("ring_velocity")
        k = self.chain.sites_per_ring
        return self.u.reshape(*self.u.shape[:-1], -1, k).mean(axis=-1)

    # -- the sensor helpers (one run) --------------------------------------------------------------
    def sensor(self, ring: int) -> np.ndarray:
        """Sensor force of ring ``ring`` (index from the impact end), N, shape (T,), or (B, T) for a batch (read-only:
        computed once per ring and shared by the sensor helpers below, which read a batch's runs at once and
        give one value per run)."""
        i = self._ring(ring)
        if i not in self._sensors:
            force = self._sensor(np.array([i]))[..., 0]
            force.flags.writeable = False
            self._sensors[i] = force
        return self._sensors[i]

    @functools.cached_property
    def _sensors(self) -> dict:
        """What was read from this run's sensors: force by ring, ("peak", ring) the leading peak's (time, force)."""
        return {}

    def _ring(self, ring) -> int:
        i = self.chain.ring_index(ring)
        if self.rings is not None and i not in self.rings:
            raise ValueError(f"ring {i} was not recorded: this run kept rings {list(self.rings)} only (rings=...)")
        return i

    def _peak(self, ring: int, threshold) -> tuple[float, float]:
        """(time, force) of the leading peak at the sensor in ``ring`` (:func:`~.signals.peak`), read once per ring
        at the default threshold."""
        if threshold is not None:
            return signals.peak(self.t, self.sensor(ring), threshold)
        i = self._ring(ring)
        if ("peak", i) not in self._sensors:
            self._sensors["peak", i] = signals.peak(self.t, self.sensor(i))
        return self._sensors["peak", i]

    def peak_force(self, ring: int, threshold=None) -> float:
        """Peak of the leading pulse read by the sensor in ``ring``, N (static tension included)."""
        return self._peak(ring, threshold)[1]

    def arrival_time(self, ring: int, threshold=None) -> float:
        """Time of the leading peak at the sensor in ``ring``, s, from the impact."""
        return self._peak(ring, threshold)[0]

    def _pair(self, near, far) -> tuple[int, int]:
        near, far = self._ring(near), self._ring(far)
        if not near < far:
            raise ValueError(f"the far ring must lie further from the impact than the near one, got near = {near}, "
                             f"far = {far}")  # fmt: skip
        return near, far

    def time_of_flight(self, near: int, far: int, threshold=None) -> float:
        """Time between the leading peaks at two sensors, s (``near`` < ``far``, counted from the impact; as
        :func:`~.signals.time_of_flight`, each trace with its own baseline)."""
        near, far = self._pair(near, far)
        return self.arrival_time(far, threshold) - self.arrival_time(near, threshold)

    def wave_speed(self, near: int, far: int, threshold=None) -> float:
        """(far - near) a over the time of flight, m/s (as measured in the paper)."""
        near, far = self._pair(near, far)
        a = self.chain.a
        distance = (far - near) * a if np.ndim(a) == 0 else float(np.sum(a[near:far]))  # centre to centre
        return signals.speed_over(distance, self.time_of_flight(near, far, threshold))

    def pulse_width(self, ring: int, threshold=None) -> float:
        """Full width at half maximum of the leading pulse at the sensor in ``ring``, s."""
        return signals.pulse_width(self.t, self.sensor(ring), threshold)

    def to_csv(self, path) -> None:
        """Write t (s), the contact forces and the support force (N) as CSV columns."""
        columns = {"t_s": self.t}
        for i in range(self.chain.n_rings - 1):
            columns[f"contact_{i}_{i + 1}_N"] = self.contact_force[:, i]
        if self.support_force is not None:
            columns["support_N"] = self.support_force
        with replacing(path) as tmp, open(tmp, "w", newline="") as handle:  # whole or not at all
            writer = csv.writer(handle)
            writer.writerow(columns)
            writer.writerows(np.column_stack(list(columns.values())).tolist())


@dataclass(frozen=True, eq=False)
class BatchSimulation(Simulation):
    """B runs of one chain: arrays of shape (B, T, ...); ``result[i]`` is run i as a :class:`Simulation`.

    The sensor helpers read every run at once (:func:`~ringchain.numerics.signals.peak` on the batch's traces) and
    give one value per run, shape (B,): ``batch.peak_force(6)[i] == batch[i].peak_force(6)``; a run whose pulse
    cannot be read raises its error, naming it ("trace i")."""

    def __len__(self) -> int:
        return self.x.shape[0]

    def __getitem__(self, i) -> Simulation:
        i = range(len(self))[i]
        return Simulation(
            t=self.t, x=self.x[i], u=self.u[i], dissipated=self.dissipated[i], g=self.g, network=self.network,
            stats=self.stats, sites=self.sites, chain=self.chain, impact_velocity=float(self.impact_velocity[i]),
            drop_height=None if self.drop_height is None else float(self.drop_height[i]), rings=self.rings,
            memory=None if self.memory is None else self.memory[i],
        )  # fmt: skip

    def __iter__(self):
        return (self[i] for i in range(len(self)))
