r"""A lattice as a network: sites with masses, links between them, a contact law on each link.

Every lattice of the package is a :class:`Network`: the power-law chain of paper Eq. (7) (one
site per ring, a :class:`~ringchain.numerics.laws.PowerLaw` contact between neighbours), the
dual-spring chain of Eqs. (5)-(6) (two sites of mass m/2 per ring joined by the bending
spring, rings joined by the Hertz contact), chains that change along their length, sheets of
rings.  A layout (:class:`~ringchain.numerics.Chain`, a sheet) builds the network; the engine
(:mod:`ringchain.numerics.engine.integrate`) integrates it.

- **Sites**: inertial mass m (kg), the mass gravity acts on (kg), ``dim`` displacement
  components (1: along the chain axis; 2 or 3: in space, the last component vertical), an
  optional rest position (m) and the ring each site belongs to (a dual-spring ring is two
  sites).
- **Links**: two sites i and j, or a site and a fixed point (``j = ANCHOR``: the support),
  and a law (:mod:`ringchain.numerics.laws`).  The extension delta of a link is the growth of
  the distance between its ends (tension positive): in one dimension delta = x_j - x_i (x the
  displacements from the configuration with every link just taut and unloaded; an anchor is
  at 0), in two or three dimensions |r_j - r_i| - L0 with r = rest position + displacement and
  L0 the rest length, the force acting along the link.  A positive force pulls its two sites
  together.  In a periodic network (a sheet with periodic sides) a link's far end may be the
  periodic image of site j, its rest position shifted by a lattice period (``Links.shift``).

The dynamics contract (what every integrator of :mod:`ringchain.numerics.engine.integrate` calls;
the ring-resolved chain, :class:`~ringchain.numerics.RingChain`, implements it too):

- ``n_coords`` -- coordinates of one run (sites x components); ``damped``;
- ``stepper(batch_shape, g)`` -- a function ``(x, u, out)`` writing the accelerations into
  ``out`` and returning the power taken out by the dashpots (None if undamped): the inner
  loop, no allocation;
- ``first_order_rhs(n_runs, g)`` -- f(t, y) of ``n_runs`` runs as one flat state for SciPy,
  and ``bandwidth``, the bands of its Jacobian;
- ``energy(x, u, x_start, g, dissipated)`` -- an :class:`~ringchain.numerics.EnergyBudget`;
- ``scales(x0, u0, g)`` -- displacement, velocity and energy scales of each run (the
  absolute tolerances);
- ``max_frequency(X)`` -- a bound on the fastest linearised mode when the links carry up to
  four times the force of extension X (the Verlet step).

The fastest mode.  A one-dimensional network whose links join site k to k + 1 (and the last
site to an anchor) -- every chain -- is a path: extensions and forces are then differences of
shifted slices of the state, and the force of each law is computed on a slice of the links
(a view), about ten NumPy operations per evaluation whatever the number of laws.  Other
networks gather and scatter through index arrays and a sparse incidence matrix.  With equal
site masses the laws are divided by the mass once, so that the forces come out per unit mass.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from ringchain.theory import STANDARD_GRAVITY
from ringchain.theory import _validate as v

from .laws import Law, one_or_all
from .results import EnergyBudget, NetworkBatch

__all__ = ["ANCHOR", "Links", "Network"]

#: The ``j`` of a link whose far end is a fixed point (the support).
ANCHOR = -1


@dataclass(frozen=True, eq=False)
class Links:
    """A set of links of one law.

    Parameters
    ----------
    i, j : int or array_like of int
        The sites each link joins; ``j = ANCHOR`` (-1) for a link to a fixed point.
    law : Law
        Its law, parameters one number or one per link.
    anchor : array_like, shape (n_links, dim), optional
        Rest positions of the fixed points of anchored links, m (networks in two or three
        dimensions; default the origin).
    index : array_like of int, optional
        Where these links stand in the network's order of links (its :attr:`Network.i`,
        :attr:`Network.j` and the columns of a run's ``link_force``): given for every set of a
        network or for none (then the sets follow one another).  A chain interleaves its
        bending springs and contacts so that link k joins site k to site k + 1.
    shift : array_like, shape (n_links, dim) or (dim,), optional
        For a periodic network (two or three dimensions): the far end of each link is the
        periodic image of site j, displaced by ``shift`` (m; a lattice period), so that its rest
        position is ``positions[j] + shift``; default 0 (site j itself).
    prestretch : float or array_like, shape (n_links,), optional
        Extension of each link with both its ends at their rest positions, m (two or three
        dimensions; default 0: the rest positions are the unloaded lattice).  A pretensioned
        lattice whose rest positions are its static state gives each link its static extension
        here: its unloaded length is the distance of its ends less the prestretch.
    """

    i: np.ndarray
    j: np.ndarray
    law: Law
    anchor: np.ndarray | None = None
    index: np.ndarray | None = None
    shift: np.ndarray | None = None
    prestretch: np.ndarray | None = None

    def __post_init__(self):
        i = np.atleast_1d(np.asarray(self.i))
        j = np.broadcast_to(np.atleast_1d(np.asarray(self.j)), i.shape)
        for name, value in (("i", i), ("j", j)):
            if value.ndim != 1 or (value.size and value.dtype.kind not in "iu"):
                raise ValueError(f"link sites {name} must be integers (one per link), got {value!r}")
        if not callable(getattr(self.law, "force_into", None)):  # a Law (duck-typed: doctests load modules twice)
            raise TypeError(f"law must be a ringchain.numerics.laws.Law, got {type(self.law).__name__}")
        object.__setattr__(self, "i", i.astype(np.intp))
        object.__setattr__(self, "j", np.array(j, dtype=np.intp))
        if self.index is not None:
            index = np.atleast_1d(np.asarray(self.index))
            if index.shape != i.shape or (index.size and index.dtype.kind not in "iu"):
                raise ValueError(f"index must give one position (an integer) per link, got {self.index!r}")
            object.__setattr__(self, "index", index.astype(np.intp))
        shape = self.law._shape()
        if shape and shape[-1] != i.size:
            raise ValueError(f"the law has parameters for {shape[-1]} links, the set has {i.size}")

    @property
    def size(self) -> int:
        return self.i.size


def _slice_of(index: np.ndarray):
    """``index`` as a slice if it is an arithmetic progression with a positive step, else None."""
    if index.size == 0:
        return None
    if index.size == 1:
        return slice(int(index[0]), int(index[0]) + 1)
    step = int(index[1] - index[0])
    if step > 0 and np.all(np.diff(index) == step):
        return slice(int(index[0]), int(index[-1]) + 1, step)
    return None


class Network:
    """Sites and links: a lattice the engine integrates (see the module notes).

    Parameters
    ----------
    mass : array_like, shape (n_sites,)
        Inertial mass of each site, kg.
    links : sequence
        :class:`Links` sets, or ``(i, j, law)`` tuples for one link each; the order of the
        links (:attr:`link_force` columns) is the order given.  Laws of one class are
        integrated as one set.
    weight_mass : array_like, shape (n_sites,), optional
        Mass of each site that gravity acts on, kg (default ``mass``).
    dim : {1, 2, 3}, optional
        Displacement components per site.
    positions : array_like, shape (n_sites, dim), optional
        Rest positions, m: needed in two or three dimensions (the links' directions and rest
        lengths); in one dimension only the length scale of :meth:`scales` uses them.
    rings : array_like of int, shape (n_sites,), optional
        The ring each site belongs to (default: each site a ring of its own).

    Examples
    --------
    Three rings of a power-law chain hanging from a support, built link by link:

    >>> from ringchain.numerics.laws import PowerLaw
    >>> law = PowerLaw(K=4.9e6, n=1.11)
    >>> net = Network([3e-3, 3e-3, 3e-3], [(0, 1, law), (1, 2, law), (2, ANCHOR, law)])
    >>> net.n_sites, net.n_links, net.is_path
    (3, 3, True)
    """

    def __init__(self, mass, links, *, weight_mass=None, dim=1, positions=None, rings=None):
        mass = np.array(v.positive("mass", mass, "kg"), dtype=float)
        if mass.ndim < 1 or mass.shape[-1] < 1:
            raise ValueError(f"mass must hold one value per site, got shape {mass.shape}")
        S = mass.shape[-1]
        weight = mass if weight_mass is None else np.array(v.nonnegative("weight_mass", weight_mass, "kg"))
        weight = np.broadcast_to(weight, mass.shape).astype(float)
        if dim not in (1, 2, 3):
            raise ValueError(f"dim must be 1, 2 or 3 displacement components, got {dim!r}")
        self.mass, self.weight_mass, self.dim = mass, weight, int(dim)
        if positions is not None:
            positions = np.array(v.as_float("positions", positions), dtype=float).reshape(S, -1)
            if positions.shape[1] != dim:
                raise ValueError(f"positions must have shape (n_sites, {dim}), got {positions.shape}")
        elif dim > 1:
            raise ValueError("a network in two or three dimensions needs the sites' rest positions")
        self.positions = positions
        rings = np.arange(S) if rings is None else np.asarray(rings)
        if rings.shape != (S,) or rings.dtype.kind not in "iu" or np.any(rings < 0):
            raise ValueError(f"rings must give a ring index (>= 0) for each of the {S} sites")
        self.rings = rings.astype(np.intp)
        sets = [item if isinstance(item, Links) else Links(*item) for item in links]
        if not sets:
            raise ValueError("a network needs at least one link")
        L = sum(s.size for s in sets)
        if any(s.index is not None for s in sets):
            if any(s.index is None for s in sets):
                raise ValueError("give the index of every set of links, or of none")
            position = np.concatenate([s.index for s in sets])
            if not np.array_equal(np.sort(position), np.arange(L)):
                raise ValueError(f"the links' indices must number them 0..{L - 1}, each once")
        else:
            position = np.arange(L)
        self.i, self.j = np.empty(L, dtype=np.intp), np.empty(L, dtype=np.intp)
        self.i[position] = np.concatenate([s.i for s in sets])
        self.j[position] = np.concatenate([s.j for s in sets])
        for name, sites in (("i", self.i), ("j", self.j[self.j != ANCHOR])):
            if np.any((sites < 0) | (sites >= S)):
                raise ValueError(f"link site {name} out of range: sites are 0..{S - 1} (j = ANCHOR for the support)")
        if np.any(self.i == self.j):
            raise ValueError("a link joins two different sites")
        anchors, shifts, stretch = np.zeros((L, dim)), np.zeros((L, dim)), np.zeros(L)
        start = 0
        for s in sets:
            where = position[start : start + s.size]
            for given, into in ((s.anchor, anchors), (s.shift, shifts)):
                if given is not None:
                    into[where] = np.broadcast_to(np.asarray(given, dtype=float), (s.size, dim))
            if s.prestretch is not None:
                stretch[where] = np.broadcast_to(v.as_float("prestretch", s.prestretch), (s.size,))
            start += s.size
        if (np.any(shifts) or np.any(stretch)) and (positions is None or dim == 1):
            raise ValueError("links to periodic images (shift) and prestretched links are for networks in two or "
                             "three dimensions, with the sites' rest positions")  # fmt: skip
        self.anchor_positions, self.shifts, self.prestretch = anchors, shifts, stretch
        # One set per law class, in the order the classes first appear, its links in the network's order.
        groups: dict[type, list] = {}
        start = 0
        for s in sets:
            groups.setdefault(type(s.law), []).append((position[start : start + s.size], s))
            start += s.size
        merged = []
        for parts in groups.values():
            law = type(parts[0][1].law).concat([s.law for _, s in parts], [s.size for _, s in parts])
            index = np.concatenate([index for index, _ in parts])
            order = np.argsort(index, kind="stable")
            if np.any(order != np.arange(order.size)):
                law = law.take(order) if law._shape() else law
            merged.append((law, index[order]))
        self.groups = tuple(merged)
        self._check_batch()

    def _check_batch(self):
        for law, _ in self.groups:
            shape = law._shape()
            if len(shape) > 1 and shape[:-1] != self.batch_shape:
                raise ValueError(f"law parameters of batch shape {shape[:-1]} on sites of batch shape "
                                 f"{self.batch_shape}")  # fmt: skip

    # -- shape ----------------------------------------------------------------------------------
    @property
    def n_sites(self) -> int:
        return self.mass.shape[-1]

    @property
    def n_links(self) -> int:
        return self.i.size

    @property
    def n_coords(self) -> int:
        """Coordinates of one run: sites x components."""
        return self.n_sites * self.dim

    @property
    def batch_shape(self) -> tuple:
        """() for one network; (B,) for a :meth:`stack` of B networks."""
        return self.mass.shape[:-1]

    @property
    def n_rings(self) -> int:
        return int(self.rings.max()) + 1

    @functools.cached_property
    def anchored(self) -> np.ndarray:
        """Whether each link ends at a fixed point."""
        return self.j == ANCHOR

    @functools.cached_property
    def damped(self) -> bool:
        """Whether any law has a dashpot (the motion then depends on velocities)."""
        return any(law.damped for law, _ in self.groups)

    @functools.cached_property
    def stateful(self) -> tuple:
        """Names of the laws with internal state (a memory per link, as :class:`~ringchain.numerics.laws.Thornton`);
        empty (false) if none."""
        return tuple(type(law).__name__ for law, _ in self.groups if law.n_state)

    def initial_memory(self) -> np.ndarray:
        """The memory of every link before a run (its law's ``delta_max``, 0 for laws without), m, shape
        (B or 1, n_links)."""
        out = np.zeros((self.batch_shape[0] if self.batch_shape else 1, self.n_links))
        for law, index in self.groups:
            if law.n_state:
                out[:, index] = np.broadcast_to(law.delta_max, (out.shape[0], index.size))
        return out

    def remembered(self, memory) -> Network:
        """The same network whose laws with memory start from ``memory`` (m per link, e.g. the end of a run)."""
        memory = np.asarray(memory, dtype=float)
        if memory.shape[-1] != self.n_links or self.batch_shape:
            raise ValueError(f"memory must give one value per link ({self.n_links}) of one network, got {memory.shape}")
        out = object.__new__(type(self))
        out.__dict__.update({k: val for k, val in self.__dict__.items() if k in (*_LAYOUT, "mass", "weight_mass")})
        out.groups = tuple((law.remembered(memory[index]) if law.n_state else law, index) for law, index in self.groups)
        return out

    def _law_call(self, law, method, e, memory, index, *args):
        """``law.method(e, *args)``, with the memory of the links ``index`` for laws with memory."""
        if law.n_state and memory is not None:
            return getattr(law, method)(e, *args, memory=np.asarray(memory)[..., index])
        return getattr(law, method)(e, *args)

    def law_of(self, link: int) -> Law:
        """The law of one link (its parameters as numbers)."""
        for law, index in self.groups:
            hit = np.flatnonzero(index == link)
            if hit.size:
                return law.take(int(hit[0]))
        raise ValueError(f"link {link} is not in a network of {self.n_links} links")

    @functools.cached_property
    def ring_mass(self) -> np.ndarray:
        """Inertial mass of each ring, kg, shape (..., n_rings)."""
        masses = np.zeros((*self.batch_shape, self.n_rings))
        np.add.at(masses, (..., self.rings), self.mass)
        return masses

    @functools.cached_property
    def rest_vectors(self) -> np.ndarray | None:
        """Vector from site i to the far end of each link at rest, m, shape (n_links, dim) (None in one
        dimension without positions): to site j (or its periodic image, ``shift``) or to the anchor."""
        if self.positions is None:
            return None
        far = np.where(
            self.anchored[:, None], self.anchor_positions,
            self.positions[np.where(self.anchored, 0, self.j)] + self.shifts,
        )  # fmt: skip
        return far - self.positions[self.i]

    @functools.cached_property
    def spans(self) -> np.ndarray | None:
        """Distance between the two ends of each link at their rest positions, m (:attr:`rest_vectors`)."""
        return None if self.positions is None else np.sqrt(np.sum(self.rest_vectors**2, axis=-1))

    @functools.cached_property
    def rest_lengths(self) -> np.ndarray | None:
        """Unloaded length of each link, m: :attr:`spans` less the ``prestretch`` (:class:`Links`); None in one
        dimension without positions."""
        return None if self.positions is None else self.spans - self.prestretch

    @functools.cached_property
    def length_scale(self) -> float | None:
        """The smallest distance between the centres of two rings joined by a link, m (None without positions)."""
        if self.positions is None:
            return None
        weights = np.broadcast_to(self.mass, (*self.batch_shape, self.n_sites)).reshape(-1, self.n_sites)[0]
        centres = np.zeros((self.n_rings, self.dim))
        np.add.at(centres, self.rings, weights[:, None] * self.positions)
        total = np.zeros(self.n_rings)
        np.add.at(total, self.rings, weights)
        centres /= total[:, None]
        inner = ~self.anchored
        a, b = self.rings[self.i[inner]], self.rings[self.j[inner]]
        between = (a != b) | np.any(self.shifts[inner] != 0, axis=-1)
        if not np.any(between):
            return None
        gaps = centres[b[between]] + self.shifts[inner][between] - centres[a[between]]
        return float(np.min(np.linalg.norm(gaps, axis=-1)))

    # -- batches --------------------------------------------------------------------------------
    @classmethod
    def stack(cls, networks) -> Network:
        """Networks of one layout stacked along a leading axis: one run each.

        Parameters
        ----------
        networks : sequence of Network, length B
            The same sites and links (masses and law parameters may differ).

        Returns
        -------
        Network
            Masses of shape (B, n_sites) and law parameters of shape (B, links of the law) where
            they differ (one number where every network has the same); its integrators take a
            batch of B states, run b on network b.
        """
        networks = list(networks)
        if not networks:
            raise ValueError("stack needs at least one network")
        first = networks[0]
        for k, net in enumerate(networks):
            if not isinstance(net, Network):
                raise TypeError(f"networks[{k}] must be a Network, got {type(net).__name__}")
            if net.batch_shape:
                raise ValueError(f"networks[{k}] is already a stack of {net.batch_shape[0]} networks")
            same = (net.dim == first.dim and net.n_sites == first.n_sites and np.array_equal(net.i, first.i)
                    and np.array_equal(net.j, first.j) and len(net.groups) == len(first.groups)
                    and all(type(a) is type(b) and np.array_equal(ia, ib)
                            for (a, ia), (b, ib) in zip(net.groups, first.groups, strict=True)))  # fmt: skip
            if not same:
                raise ValueError(
                    f"networks of one layout are stacked: networks[{k}] has {net.n_sites} sites and "
                    f"{net.n_links} links, networks[0] {first.n_sites} and {first.n_links} (or other links or laws)"
                )
        out = object.__new__(cls)
        out.__dict__.update({k: val for k, val in first.__dict__.items() if k in _LAYOUT})
        out.mass = np.stack([net.mass for net in networks])
        out.weight_mass = np.stack([net.weight_mass for net in networks])
        out.groups = tuple(
            (type(law).stack([net.groups[g][0] for net in networks], index.size), index)
            for g, (law, index) in enumerate(first.groups)
        )  # fmt: skip
        return out

    def member(self, b: int) -> Network:
        """Network ``b`` of a :meth:`stack`."""
        if not self.batch_shape:
            raise ValueError("member takes a network of a stack; this network is not a stack")
        out = object.__new__(type(self))
        out.__dict__.update({k: val for k, val in self.__dict__.items() if k in _LAYOUT})
        out.mass, out.weight_mass = self.mass[b], self.weight_mass[b]
        out.groups = tuple(
            (law._rebuilt(**{k: p[b] if np.ndim(p) > 1 else p for k, p in law.params.items()}), index)
            for law, index in self.groups
        )  # fmt: skip
        return out

    # -- kinematics -------------------------------------------------------------------------------
    @functools.cached_property
    def _path(self):
        """For a path (module notes): the slice of each group in path order (link of site k at k), else None."""
        if self.dim != 1:
            return None
        S, L = self.n_sites, self.n_links
        if L not in (S - 1, S):
            return None
        inner, tail = ~self.anchored, self.anchored
        if np.any(self.j[inner] != self.i[inner] + 1) or np.count_nonzero(tail) > 1:
            return None
        if np.any(tail) and self.i[tail][0] != S - 1:
            return None
        if np.any(np.sort(self.i) != np.arange(L)):
            return None
        slices = [_slice_of(self.i[index]) for _, index in self.groups]
        return None if any(s is None for s in slices) else slices

    @property
    def is_path(self) -> bool:
        """Whether the network takes the fast path (a one-dimensional chain of links k -> k + 1)."""
        return self._path is not None

    @functools.cached_property
    def _incidence(self):
        """Sparse (n_coords, n_links * dim) matrix taking link force vectors to site forces."""
        from scipy.sparse import csr_matrix

        L, d = self.n_links, self.dim
        rows, cols, vals = [], [], []
        for c in range(d):
            rows.append(self.i * d + c)
            cols.append(np.arange(L) * d + c)
            vals.append(np.ones(L))
            inner = ~self.anchored
            rows.append(self.j[inner] * d + c)
            cols.append(np.flatnonzero(inner) * d + c)
            vals.append(-np.ones(np.count_nonzero(inner)))
        return csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                          shape=(self.n_coords, L * d))  # fmt: skip

    def geometry(self, x, u=None, links=None, columns=None):
        """Extensions (m) of ``links`` (default all) and their rates (m/s) if ``u`` is given, and unit vectors.

        Parameters
        ----------
        x, u : ndarray, shape (..., n_coords) or (..., len(columns) * dim)
            Displacements (m) and velocities (m/s).
        links : array_like of int, optional
        columns : array_like of int, optional
            The sites whose coordinates ``x`` holds (sorted), when it holds only some.

        Returns
        -------
        e, rate, direction
            Shapes (..., n) each (rate None without ``u``); ``direction`` (..., n, dim) points from
            i to j (None in one dimension).
        """
        links = np.arange(self.n_links) if links is None else np.asarray(links, dtype=np.intp)
        i, j = self.i[links], self.j[links]
        anchored = j == ANCHOR
        if columns is not None:
            needed = np.concatenate([i, j[~anchored]])
            missing = needed[~np.isin(needed, columns)]
            if missing.size:
                raise ValueError(f"the forces of these links need sites {sorted(set(missing.tolist()))}, which were "
                                 "not recorded (record their rings, or every ring)")  # fmt: skip
        where = (lambda s: s) if columns is None else (lambda s: np.searchsorted(columns, s))
        ci, cj = where(i), where(np.where(anchored, i, j))
        d = self.dim
        if d == 1:
            far = np.where(anchored, 0.0, x[..., cj])
            e = far - x[..., ci]
            rate = None if u is None else np.where(anchored, 0.0, u[..., cj]) - u[..., ci]
            return e, rate, None
        # The extension from the rest vector b and the relative displacement w of the ends:
        # |b + w| - |b| = (2 b.w + w.w)/(|b + w| + |b|), without the cancellation of two lengths of order
        # |b| (the extension keeps its own relative precision, as x_j - x_i does in one dimension), plus the
        # prestretch (the extension at the rest positions, given exactly).
        X = x.reshape(*x.shape[:-1], -1, d)
        b = self.rest_vectors[links]
        w = np.where(anchored[:, None], 0.0, X[..., cj, :]) - X[..., ci, :]
        delta = b + w
        length = np.sqrt(np.sum(delta * delta, axis=-1))
        direction = delta / length[..., None]
        e = np.sum((2.0 * b + w) * w, axis=-1) / (length + self.spans[links]) + self.prestretch[links]
        rate = None
        if u is not None:
            U = u.reshape(*u.shape[:-1], -1, d)
            du = np.where(anchored[:, None], 0.0, U[..., cj, :]) - U[..., ci, :]
            rate = np.sum(du * direction, axis=-1)
        return e, rate, direction

    def extension(self, x) -> np.ndarray:
        """Extension of every link, m, shape (..., n_links)."""
        return self.geometry(np.asarray(x, dtype=float))[0]

    def forces(self, e, rate=None, memory=None) -> np.ndarray:
        """Force of every link, N, from the links' extensions ``e`` (m) and rates (m/s; read if damped), shape
        (..., n_links); ``memory`` (m, per link) for laws with memory (default their initial memory)."""
        e = np.asarray(e, dtype=float)
        out = np.empty_like(e)
        for law, index in self.groups:
            out[..., index] = self._law_call(law, "force", e[..., index], memory, index,
                                             None if rate is None else np.asarray(rate)[..., index])  # fmt: skip
        return out

    def link_energy(self, e, memory=None) -> np.ndarray:
        """Energy stored in every link at extensions ``e``, J, shape (..., n_links) (``memory`` as :meth:`forces`)."""
        e = np.asarray(e, dtype=float)
        out = np.empty_like(e)
        for law, index in self.groups:
            out[..., index] = self._law_call(law, "energy", e[..., index], memory, index)
        return out

    def stiffness(self, e) -> np.ndarray:
        """Tangent stiffness dF/d(delta) of every link at extensions ``e``, N/m, shape (..., n_links)."""
        e = np.asarray(e, dtype=float)
        out = np.empty_like(e)
        for law, index in self.groups:
            out[..., index] = law.stiffness(e[..., index])
        return out

    def extension_at(self, tension) -> np.ndarray:
        """Extension of every link carrying the static ``tension`` (N; one number or one per link), m."""
        tension = np.broadcast_to(np.asarray(tension, dtype=float), (self.n_links,))
        out = np.empty(self.n_links)
        for law, index in self.groups:
            out[index] = law.static_extension(tension[index])
        return out

    def dissipation_rate(self, e, rate) -> np.ndarray:
        """Power the dashpots take out, W, summed over the links (shape (...)); never negative."""
        e, rate = np.asarray(e, dtype=float), np.asarray(rate, dtype=float)
        power = np.zeros(e.shape[:-1])
        for law, index in self.groups:
            if law.damped:
                power = power + np.sum(law.dissipation(e[..., index], rate[..., index]), axis=-1)
        return power

    def link_forces(self, x, u=None, links=None, columns=None, elastic=False, memory=None) -> np.ndarray:
        """Force of ``links`` (default all), N, positive in tension, shape (..., n); see :meth:`geometry`.

        ``u`` is read only if the network is damped; ``elastic`` leaves out the dashpots; ``memory`` (m, every
        link: shape (..., n_links)) for laws with memory.
        """
        links = np.arange(self.n_links) if links is None else np.asarray(links, dtype=np.intp)
        e, rate, _ = self.geometry(x, u if (self.damped and not elastic) else None, links, columns)
        out = np.empty_like(e)
        for law, index in self.groups:
            hit = np.isin(links, index)
            if not np.any(hit):
                continue
            part = law.take(np.searchsorted(index, links[hit])) if not np.array_equal(index, links[hit]) else law
            if part._shape() and len(part._shape()) > 1:  # a stack: parameters (B, n) against e (B, T, n)
                part = part._rebuilt(**{k: p[:, None, :] if np.ndim(p) > 1 else p for k, p in part.params.items()})
            out[..., hit] = self._law_call(part, "force", e[..., hit], memory, links[hit],
                                           None if rate is None else rate[..., hit])  # fmt: skip
        return out

    # -- the dynamics contract ---------------------------------------------------------------------
    @property
    def bandwidth(self) -> tuple[int, int]:
        """Lower and upper bandwidth of the Jacobian of :meth:`first_order_rhs` (site-interleaved state).

        The velocity of a site depends on x and u of the sites it is linked to; with sites
        numbered along a chain (a span of 1) that is (3, 2).
        """
        inner = ~self.anchored
        span = int(np.max(np.abs(self.j[inner] - self.i[inner]), initial=0))
        d = self.dim
        return 2 * d * span + 2 * d - 1, 2 * d * span + d - 1

    def stepper(self, batch_shape, g):
        """A function ``(x, u, out)`` writing the accelerations (m/s^2) of displacements ``x`` into ``out``.

        ``x``, ``u``, ``out`` have shape ``(*batch_shape, n_coords)``; ``u`` is read only if the
        network is damped, and the function then returns the power each run's dashpots take
        out (W, shape batch_shape), else None.  Work arrays are made once: a call is a few
        NumPy operations on whole arrays (module notes).  One stepper must not be called from
        two threads at once.
        """
        if self._path is not None:
            return self._path_stepper(tuple(batch_shape), g)
        return self._general_stepper(tuple(batch_shape), g)

    def _gravity_acceleration(self, g):
        """Acceleration of gravity on each coordinate, m/s^2 (a number if every site has the same)."""
        per_site = g * self.weight_mass / self.mass
        if self.dim == 1:
            return one_or_all(per_site)
        out = np.zeros((*self.batch_shape, self.n_sites, self.dim))
        out[..., -1] = per_site
        return out.reshape(*self.batch_shape, self.n_coords)

    def _path_stepper(self, batch_shape, g):
        S, L = self.n_sites, self.n_links
        slices = self._path
        e = np.empty((*batch_shape, L))
        anchored = L == S
        # Padded forces in path order: [0, link 0, ..., link L-1, (0 if the far end is free)].  Site k is
        # pulled up by its link (k) and down by the link below it (k - 1); site 0 has none below it.
        padded = np.zeros((*batch_shape, S + 1))
        f = padded[..., 1 : 1 + L]
        above, below = padded[..., 1:], padded[..., :-1]
        e_head, e_tail = e[..., : S - 1], (e[..., S - 1] if anchored else None)
        upper, lower, last = (slice(1, None), slice(None, -1), S - 1) if not batch_shape else (
            (Ellipsis, slice(1, None)), (Ellipsis, slice(None, -1)), (Ellipsis, S - 1))  # fmt: skip
        subtract, multiply = np.subtract, np.multiply
        mass = one_or_all(self.mass)
        per_mass = np.ndim(mass) == 0  # equal masses: the laws divided by m once, forces per unit mass
        laws = [law.scaled(1.0 / mass) if per_mass else law for law, _ in self.groups]
        g_acc = self._gravity_acceleration(g)
        inv_mass = None if per_mass else 1.0 / self.mass
        parts = [(law, e[..., s], f[..., s], np.empty_like(e[..., s])) for law, s in zip(laws, slices, strict=True)]
        if not self.damped:

            def accelerations_into(x, u, out):
                subtract(x[upper], x[lower], out=e_head)
                if e_tail is not None:
                    subtract(0.0, x[last], out=e_tail)  # not np.negative: see Network.extension
                for law, e_part, f_part, work in parts:
                    law.force_into(e_part, None, f_part, work)
                subtract(above, below, out=out)
                if inv_mass is not None:
                    multiply(out, inv_mass, out=out)
                subtract(out, g_acc, out=out)

            return accelerations_into

        rate = np.empty_like(e)
        rate_head, rate_tail = rate[..., : S - 1], (rate[..., S - 1] if anchored else None)
        rates = [rate[..., s] for s in slices]
        elastic = np.empty_like(e)
        elastic_parts = [elastic[..., s] for s in slices]
        scale = mass if per_mass else 1.0

        def accelerations_into(x, u, out):
            subtract(x[upper], x[lower], out=e_head)
            subtract(u[upper], u[lower], out=rate_head)
            if e_tail is not None:
                subtract(0.0, x[last], out=e_tail)
                subtract(0.0, u[last], out=rate_tail)
            for (law, e_part, f_part, work), r_part, el_part in zip(parts, rates, elastic_parts, strict=True):
                law.force_into(e_part, r_part, f_part, work)
                if law.damped:
                    law.force_into(e_part, None, el_part, work)
                else:
                    el_part[...] = f_part
            subtract(above, below, out=out)
            if inv_mass is not None:
                multiply(out, inv_mass, out=out)
            subtract(out, g_acc, out=out)
            return scale * np.sum((f - elastic) * rate, axis=-1)

        return accelerations_into

    def _general_stepper(self, batch_shape, g):
        d, L = self.dim, self.n_links
        C = self._incidence
        inv_mass = np.repeat(1.0 / self.mass, d, axis=-1)
        g_acc = self._gravity_acceleration(g)
        damped = self.damped
        groups = [(law, _slice_of(index) or index) for law, index in self.groups]

        def accelerations_into(x, u, out):
            e, rate, direction = self.geometry(x, u if damped else None)
            f = np.empty_like(e)
            for law, index in groups:
                f[..., index] = law.force(e[..., index], None if rate is None else rate[..., index])
            power = self.dissipation_rate(e, rate) if damped else None
            vectors = f if d == 1 else (f[..., None] * direction).reshape(*f.shape[:-1], L * d)
            flat = vectors.reshape(-1, L * d)
            out[...] = (C @ flat.T).T.reshape(out.shape)
            out *= inv_mass
            out -= g_acc
            return power

        return accelerations_into

    def accelerations(self, x, u=None, g=STANDARD_GRAVITY) -> np.ndarray:
        """Accelerations, m/s^2, of displacements ``x`` and velocities ``u`` (shape (..., n_coords)).

        Gravity ``g`` (m/s^2) acts on the weight masses along -axis (the last component in two or
        three dimensions); 0 for none.  ``u`` is needed only if the network is damped.
        """
        x = np.asarray(x, dtype=float)
        if self.damped and u is None:
            raise ValueError("a damped network needs the velocities u")
        out = np.empty_like(x)
        self.stepper(x.shape[:-1], g)(x, None if u is None else np.asarray(u, dtype=float), out)
        return out

    def first_order_rhs(self, n_runs: int, g: float):
        """Right-hand side f(t, y) of ``n_runs`` runs as one flat state (for SciPy's integrators).

        The state is [x, u] interleaved per site, shape (n_runs, n_sites, 2, dim), flattened,
        then the energy W dissipated so far by each run (only if the network is damped).
        Interleaving keeps the Jacobian banded (:attr:`bandwidth`), which implicit and
        stiff-switching solvers exploit; the W entries lie outside the band, which only makes
        the Newton matrix approximate (W feeds back into nothing).  A :meth:`stack` of B
        networks takes ``n_runs = B``, run b on network b.
        """
        if self.batch_shape and (n_runs,) != self.batch_shape:
            raise ValueError(
                f"a stack of {self.batch_shape[0]} networks integrates one run each, got n_runs = {n_runs}"
            )
        N, d = self.n_coords, self.dim
        n_xu = 2 * n_runs * N
        shape = () if n_runs == 1 and not self.batch_shape else (n_runs,)  # one run: plain 1-d views
        accelerations_into = self.stepper(shape, g)
        damped = self.damped
        if d == 1:  # the chains: x and u interleaved, strided views (the fast path of the old lattice, unchanged)
            x_part, u_part = slice(0, n_xu, 2), slice(1, n_xu, 2)

            def rhs(t, y):
                dy = np.empty_like(y)
                u = y[u_part]
                dy[x_part] = u
                x, a = y[x_part], dy[u_part]
                if shape:
                    x, u, a = x.reshape(n_runs, N), u.reshape(n_runs, N), a.reshape(n_runs, N)
                power = accelerations_into(x, u, a)
                if damped:
                    dy[n_xu:] = power
                return dy

            return rhs

        S = self.n_sites

        def rhs(t, y):
            dy = np.empty_like(y)
            Y, dY = y[:n_xu].reshape(n_runs, S, 2, d), dy[:n_xu].reshape(n_runs, S, 2, d)
            dY[:, :, 0] = Y[:, :, 1]
            x, u = Y[:, :, 0].reshape(n_runs, N), Y[:, :, 1].reshape(n_runs, N)
            a = np.empty((n_runs, N))
            power = accelerations_into(x if shape else x[0], u if shape else u[0], a if shape else a[0])
            dY[:, :, 1] = a.reshape(n_runs, S, d)
            if damped:
                dy[n_xu:] = power
            return dy

        return rhs

    def pack(self, x, u, dissipated=None) -> np.ndarray:
        """The flat state of :meth:`first_order_rhs` from x, u (shape (B, n_coords)) and W (B,)."""
        B, d = x.shape[0], self.dim
        xu = np.stack([x.reshape(B, -1, d), u.reshape(B, -1, d)], axis=2).ravel()
        return np.concatenate([xu, np.zeros(B) if dissipated is None else dissipated]) if self.damped else xu

    def unpack(self, y, n_runs):
        """x, u (shape (n_runs, n_coords, T)) and W (n_runs, T) or None, of states ``y`` of shape (n_state, T)."""
        n_xu = 2 * n_runs * self.n_coords
        states = y[:n_xu].reshape(n_runs, self.n_sites, 2, self.dim, -1)
        x = states[:, :, 0].reshape(n_runs, self.n_coords, -1)
        u = states[:, :, 1].reshape(n_runs, self.n_coords, -1)
        return x, u, (y[n_xu:] if y.shape[0] > n_xu else None)

    def state_scales(self, X, V, E) -> np.ndarray:
        """Absolute-tolerance scales of the flat state: X per displacement, V per velocity, E per W (per run)."""
        per_site = np.repeat(np.stack([X, V], axis=-1)[:, None, :, None], self.n_sites, axis=1)
        per_site = np.broadcast_to(per_site, (X.size, self.n_sites, 2, self.dim)).ravel()
        return np.concatenate([per_site, E]) if self.damped else per_site

    def energy(self, x, u, x_start, g, dissipated, memory=None):
        """Kinetic, contact, bending, gravity, dissipated and plastic energy, J, each of shape (...); ``memory`` (m,
        shape (..., n_links)) of laws with one (default their initial memory), plastic work from a virgin contact."""
        x = np.asarray(x)

        def per_member(p):  # a stack's (B, n) parameters against states (B, n) or (B, T, n)
            p = np.asarray(p)
            return p.reshape(p.shape[0], *(1,) * (x.ndim - 2), p.shape[-1]) if p.ndim > 1 else p

        mass = per_member(np.repeat(self.mass, self.dim, axis=-1))
        e, _, _ = self.geometry(x)
        stored = {"contact": np.zeros(e.shape[:-1]), "bending": np.zeros(e.shape[:-1])}
        plastic = np.zeros(e.shape[:-1])
        for law, index in self.groups:
            part = law
            if len(law._shape()) > 1:
                part = law._rebuilt(**{k: per_member(p) for k, p in law.params.items()})
            stored[law.energy_kind] = stored[law.energy_kind] + np.sum(
                self._law_call(part, "energy", e[..., index], memory, index), axis=-1)  # fmt: skip
            if law.n_state:
                plastic = plastic + np.sum(self._law_call(part, "plastic_work", e[..., index], memory, index), axis=-1)
        weight = per_member(self.weight_mass)
        height = np.asarray(x - x_start)
        if self.dim > 1:
            height = height.reshape(*height.shape[:-1], -1, self.dim)[..., -1]
        return EnergyBudget(
            kinetic=0.5 * np.sum(mass * np.square(u), axis=-1),
            contact=stored["contact"],
            bending=stored["bending"],
            gravity=g * np.sum(weight * height, axis=-1),
            dissipated=dissipated,
            plastic=plastic,
        )

    def scales(self, x0, u0, g):
        """Displacement (m), velocity (m/s) and energy (J) scales of each run, shape (B,) each.

        The velocity scale is the largest initial speed (the impact speed), floored at
        1e-3 sqrt(g a) with a the smallest distance between linked rings, for a run without
        impact.  The energy scale is m V^2/4 with m the heaviest ring: the energy of a two-ring
        collision, half the impact's.  The displacement scale is the sum over the laws of the
        largest extension at which a link of that law stores this energy (contact and bending in
        series for the dual-spring chain), or the largest initial extension if larger.  Each run
        of a batch has its own scales, so that a small impact beside a large one keeps its own
        accuracy.
        """
        speeds = np.max(np.abs(u0), axis=-1)
        a = self.length_scale
        floor = 1e-9 if a is None else max(1e-3 * math.sqrt(g * a), 1e-9)
        speed = np.maximum(speeds, floor)
        ring_mass = self.ring_mass
        energy = 0.25 * np.max(ring_mass, axis=-1) * speed**2
        X = 0.0
        for law, _ in self.groups:  # per link, (B, links of the law) or (B, 1) for a law that is one number
            X = X + np.max(law.extension_at_energy(energy[..., None]), axis=-1)
        X = np.maximum(X, np.max(np.abs(self.extension(x0)), axis=-1, initial=0.0))
        return X, speed, energy

    def max_frequency(self, X) -> float:
        """omega_max, rad/s: sqrt(2 z k_max / m_min), z the most links at a site, k_max the largest
        tangent stiffness up to four times the force at extension ``X`` (Gershgorin's bound; in a
        chain, z = 2: 2 sqrt(k_max/m_min))."""
        k_max = max(float(np.max(law.stiffness_bound(X))) for law, _ in self.groups)
        counts = np.bincount(np.concatenate([self.i, self.j[~self.anchored]]), minlength=self.n_sites)
        return math.sqrt(2.0 * int(counts.max()) * k_max / float(np.min(self.mass)))

    # -- the model contract (ringchain.numerics.engine.integrate): a network integrated as it is -------------
    def dynamics(self) -> Network:
        return self

    def impact_state(self, speeds, dropped, gravity, g):
        """A network has no struck ring: at rest with every link just taut, unless an impact is asked for."""
        if dropped or np.any(speeds):
            raise ValueError("a network has no struck ring: give its initial state, initial=(x0, u0), or simulate a "
                             "layout (a Chain) that knows where it is struck")  # fmt: skip
        runs = self.batch_shape[0] if self.batch_shape else speeds.size
        return np.zeros((runs, self.n_coords)), np.zeros((runs, self.n_coords))

    def recorded(self, rings):
        """The rings to record and the coordinates of their sites; (None, None) for all."""
        if rings is None:
            return None, None
        values = sorted({v.integer("ring", r) for r in ([rings] if np.ndim(rings) == 0 else rings)})
        if not values or values[0] < 0 or values[-1] >= self.n_rings:
            raise ValueError(f"rings must name rings of the network (0..{self.n_rings - 1}), got {rings!r}")
        sites = self.ring_site_indices(values)
        return tuple(values), (sites[:, None] * self.dim + np.arange(self.dim)).ravel()

    def ring_site_indices(self, rings) -> np.ndarray:
        """The sites of ``rings`` (ring indices), sorted."""
        return np.flatnonzero(np.isin(self.rings, rings))

    def result(self, *, rings=None, impact_velocity=None, drop_height=None, **record):
        """The record of a batch of runs of this network (:class:`~ringchain.numerics.NetworkBatch`)."""
        sites = None if rings is None else self.ring_site_indices(rings)
        return NetworkBatch(network=self, sites=sites, **record)


#: The attributes of a network that a :meth:`Network.stack` shares with its first network.
_LAYOUT = ("dim", "positions", "rings", "i", "j", "anchor_positions", "shifts", "prestretch")


def as_links(items: Sequence) -> list[Links]:
    """``(i, j, law)`` tuples and :class:`Links` as a list of :class:`Links`."""
    return [item if isinstance(item, Links) else Links(*item) for item in items]
