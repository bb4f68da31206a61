r"""Compiled fields of a recorded run: link forces and energies over every sample and link at once (Numba).

What a run of a network in two or three dimensions (a sheet) reads after its integration -- the force of
each link at each sample (:attr:`~ringchain.numerics.NetworkSimulation.link_force`) and the energy budget
(:meth:`~ringchain.numerics.NetworkSimulation.energy`) -- computed in one compiled pass over the samples,
from the packed network (:func:`~ringchain.numerics.engine.packing.pack`) and the recorded states.  The
NumPy path (:meth:`~ringchain.numerics.Network.link_forces`, :meth:`~ringchain.numerics.Network.energy`)
stays as the independent reference the tests compare against; a chain (one dimension) keeps it, its
slices being as fast as a kernel, so that a chain's first command never compiles this module.

Per link and sample: the extension from the rest vector b and the relative displacement w of the ends,
(2 b.w + w.w)/(|b + w| + |b|) plus the prestretch (as :meth:`~ringchain.numerics.Network.geometry`: no
cancellation of two lengths of order |b|), its rate along the link where a law is damped, then the law
(the kinds of :data:`~ringchain.numerics.engine.packing.LAW_KINDS`): the force, and the elastic energy
from the elastic force F_e itself, F_e delta/(n + 1) for the power law K delta^n (paper Eq. (4)) and
Hunt-Crossley's elastic part, F_e delta/2 for the linear spring, none for the dashpot.  Thornton's contact
takes its memory at each sample (what the integrator returns per sample, m); its stored energy and plastic
work come from :mod:`ringchain.theory.plastic` in NumPy, for its links only.  Per sample, besides: the
kinetic energy sum m u^2/2 and the work of gravity g sum m_g (z - z_0) from the first sample.

Samples are split over a pool of threads (the kernels release the GIL).  Kernels are small and few (one
per idea), compiled on first use and cached on disk with the engine's other kernels
(:func:`~ringchain.numerics.engine._compiled.jit`); none calls a kernel of another module.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from ._compiled import jit
from ._kernel_calls import kernel_array, over_threads
from .kernels import law_force
from .packing import LAW_KINDS, pack

__all__ = ["Fields", "compiles", "fields"]

#: Samples x links below which the kernels run on the calling thread (a pool costs more than it saves).
_THREADED_WORK = 200_000


@jit()
def _law(kind, p0, p1, p2, e, rate, memory):
    """(force, elastic energy) of one link of law ``kind`` (parameters p0-p2) at extension ``e`` and its rate: the
    kernels' force (:func:`~ringchain.numerics.engine.kernels.law_force`) and the energy stored by its elastic part
    (K delta^(n+1)/(n+1) for the power laws, K delta^2/2 for a spring); Thornton's is left to NumPy (0 here)."""
    force, elastic = law_force(kind, p0, p1, p2, e, rate, memory)
    if kind == 0 or kind == 4:
        return force, (elastic * e / (p1 + 1.0) if e > 0.0 else 0.0)
    if kind == 1:
        return force, 0.5 * elastic * e
    return force, 0.0


@jit(nogil=True)
def _links(m, bp, x, u, memory, links, ci, cj, damped, force, stored, first, last):
    """Forces of ``links`` into ``force`` (T, n; width 0: none) and the elastic energy of every link, summed
    as contact (kinds 0, 3, 4) and bending (1, 2), into ``stored`` (T, 2; rows 0: none), samples first to last.

    ``ci``, ``cj``: the first coordinate of each link's two sites in a row of ``x`` (-1: a fixed point).
    """
    d = m.ints[1]
    par = m.par[bp]
    for t in range(first, last):
        xt, ut = x[t], u[t]
        for q in range(links.size):
            k = links[q]
            i, j = ci[q], cj[q]
            rate = 0.0
            if d == 1:
                e = (xt[j] if j >= 0 else 0.0) - xt[i]
                if damped:
                    rate = (ut[j] if j >= 0 else 0.0) - ut[i]
            else:
                length2, stretch = 0.0, 0.0
                for c in range(d):
                    w = (xt[j + c] if j >= 0 else 0.0) - xt[i + c]
                    length2 += (m.rest_vectors[k, c] + w) ** 2
                    stretch += (2.0 * m.rest_vectors[k, c] + w) * w
                length = math.sqrt(length2)
                e = stretch / (length + m.spans[k]) + m.prestretch[k]
                if damped:
                    for c in range(d):
                        w = (xt[j + c] if j >= 0 else 0.0) - xt[i + c]
                        rate += ((ut[j + c] if j >= 0 else 0.0) - ut[i + c]) * (m.rest_vectors[k, c] + w) / length
            f, energy = _law(m.kind[k], par[k, 0], par[k, 1], par[k, 2], e, rate, memory[t, k] if memory.size else 0.0)
            if force.shape[1]:
                force[t, q] = f
            if stored.shape[0]:
                stored[t, 1 if m.kind[k] == 1 or m.kind[k] == 2 else 0] += energy


@jit(nogil=True)
def _motion(x, u, mass, weight, d, out, first, last):
    """Kinetic energy sum m u^2/2 and gravity's sum m_g (z - z_0) per unit g into ``out`` (T, 2), samples first to
    last; ``mass`` per coordinate, ``weight`` per site, z the last component."""
    for t in range(first, last):
        kinetic, height = 0.0, 0.0
        for c in range(x.shape[1]):
            kinetic += mass[c] * u[t, c] * u[t, c]
        for s in range(weight.size):
            c = s * d + d - 1
            height += weight[s] * (x[t, c] - x[0, c])
        out[t, 0], out[t, 1] = 0.5 * kinetic, height


class Fields(NamedTuple):
    """Link forces and energies of one run, each over its samples (see :func:`fields`)."""

    force: np.ndarray  # (T, n): the links asked for, N
    contact: np.ndarray | None  # (T,): elastic energy of the contacts, J (None: energies not asked for)
    bending: np.ndarray | None  # (T,): of the bending springs, J
    kinetic: np.ndarray | None  # (T,), J
    gravity: np.ndarray | None  # (T,): gravity's work from the first sample, J
    plastic: np.ndarray | float  # (T,): Thornton's plastic work, J (0.0 without such links)


def compiles(network) -> bool:
    """Whether :func:`fields` serves ``network``: every law of a kind the kernels know."""
    return all(type(law).__name__ in LAW_KINDS for law, _ in network.groups)


def fields(network, x, u=None, links=None, sites=None, memory=None, g=0.0, energies=False, member=0) -> Fields:
    """Forces of ``links`` and (``energies``) the energy budget of one run of ``network``, compiled.

    Parameters
    ----------
    network : Network
        Its laws of the kinds the kernels know (:func:`compiles`); for a stack, the run is of member ``member``.
    x, u : ndarray, shape (T, K)
        Displacements (m) and velocities (m/s) of the recorded sites at each sample (``u`` read where a law is
        damped, and for the kinetic energy).
    links : array_like of int, optional
        The links whose forces are wanted (default every link; empty for none).
    sites : array_like of int, optional
        The sites whose coordinates ``x`` holds, sorted (default every site); the energies need every site.
    memory : ndarray, shape (T, n_links), optional
        Laws with memory: each link's memory at each sample, m (default the laws' initial memory).
    g : float, optional
        Gravity of the run, m/s^2 (the gravity energy).
    energies : bool, optional
        Compute the energies too (in the same pass as the forces).

    Returns
    -------
    Fields
        Forces (N, positive in tension) and energies (J), as :meth:`~ringchain.numerics.Network.link_forces`
        and :meth:`~ringchain.numerics.Network.energy` give them (the dissipated energy is the run's own).
    """
    if not compiles(network):
        raise ValueError(f"the compiled fields know the laws {', '.join(LAW_KINDS)}; use Network.link_forces and "
                         "Network.energy")  # fmt: skip
    packed = pack(network)
    d, S = network.dim, network.n_sites
    x = kernel_array(x, dtype=float)
    T = x.shape[0]
    links = np.arange(network.n_links) if links is None else np.asarray(links, dtype=np.int64)
    column = np.arange(S) if sites is None else np.full(S, -1)
    if sites is not None:
        column[np.asarray(sites)] = np.arange(len(sites))
    if energies and sites is not None and len(sites) < S:
        raise ValueError(f"the energies need every site, but the run recorded {len(sites)} of {S}")
    ci, cj = column[network.i[links]], np.where(network.anchored[links], -1, column[network.j[links]])
    if np.any(ci < 0) or np.any((cj < 0) & ~network.anchored[links]):
        raise ValueError("the forces of these links need sites that were not recorded (record their rings)")
    ci, cj = ci * d, np.where(cj < 0, -1, cj * d)  # the first coordinate of each end in a row of x
    damped = bool(packed.ints[3])
    u = x if u is None else kernel_array(u, dtype=float)
    if damped and u is x:
        raise ValueError("a damped network needs the velocities u")
    if network.stateful:
        memory = np.broadcast_to(network.initial_memory()[:1], (T, network.n_links)) if memory is None else memory
    memory = kernel_array(memory, dtype=float) if network.stateful else np.zeros((0, 0))
    bp = member if packed.par.shape[0] > 1 else 0
    work = T * (network.n_links if energies else links.size)
    threaded = work >= _THREADED_WORK
    force = np.empty((T, links.size))
    stored = np.zeros((T if energies else 0, 2))
    if energies and np.array_equal(links, np.arange(network.n_links)):  # one pass: the forces and energies
        over_threads(_links, T, threaded, packed, bp, x, u, memory, links, ci, cj, damped, force, stored)
    else:
        if links.size:
            over_threads(_links, T, threaded, packed, bp, x, u, memory, links, ci, cj, damped, force, np.zeros((0, 2)))
        if energies:
            everything = np.arange(network.n_links, dtype=np.int64)
            ends = np.where(network.anchored, -1, network.j * d)
            over_threads(_links, T, threaded, packed, bp, x, u, memory, everything, network.i * d, ends, False,
                         np.zeros((T, 0)), stored)  # fmt: skip
    if not energies:
        return Fields(force, None, None, None, None, 0.0)
    own = network.member(member) if network.batch_shape else network
    motion = np.empty((T, 2))
    over_threads(_motion, T, threaded, x, u, np.repeat(own.mass, d), kernel_array(own.weight_mass, dtype=float),
                 d, motion)  # fmt: skip
    plastic = 0.0
    for law, index in own.groups:
        if law.n_state:  # Thornton's stored energy and plastic work (theory.plastic), its links only
            e = own.geometry(x, links=index)[0]
            stored[:, 0] += np.sum(law.energy(e, memory=memory[:, index]), axis=-1)
            plastic = plastic + np.sum(law.plastic_work(e, memory=memory[:, index]), axis=-1)
    return Fields(force, stored[:, 0], stored[:, 1], motion[:, 0], g * motion[:, 1], plastic)
