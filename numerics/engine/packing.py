"""Models packed for the compiled kernels (:mod:`ringchain.numerics.engine.kernels`): plain Python, no kernel.

A network or a ring-resolved chain is packed once (:func:`pack`) into a tuple of arrays of fixed types
(:class:`~ringchain.numerics.engine.kernels.Packed`, :class:`~ringchain.numerics.engine.kernels.PackedRingChain`);
the kernels' module notes say what each field holds.  Rigid rings pack themselves
(:meth:`ringchain.numerics.Rings.packed`).
"""

from __future__ import annotations

import weakref

import numpy as np

from ._compiled import Packed, PackedRingChain
from ._kernel_calls import kernel_array

__all__ = ["PARAMETERS", "LAW_KINDS", "pack", "pack_network", "pack_ring_chain"]

#: Law parameters per link (a row of the packed parameter array).
PARAMETERS = 4

#: Kind code of each law class the kernels implement, by class name.
LAW_KINDS = {"PowerLaw": 0, "LinearSpring": 1, "Dashpot": 2, "Thornton": 3, "HuntCrossley": 4}


def _empty(*shape, dtype=float):
    return np.zeros(shape, dtype=dtype)


_PACKED: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def pack(model) -> Packed:
    """The :class:`Packed` form of a network or a ring-resolved chain (the dynamics of a model), made once."""
    if model not in _PACKED:
        own = getattr(model, "packed", None)  # a model packing itself (rigid rings, kind 2)
        _PACKED[model] = own() if own else pack_ring_chain(model) if hasattr(model, "ring") else pack_network(model)
    return _PACKED[model]


def pack_network(net) -> Packed:
    """The :class:`Packed` form of a :class:`~ringchain.numerics.Network` (or of a stack of them)."""
    L, S, d = net.n_links, net.n_sites, net.dim
    batch = net.batch_shape
    Bp = 1
    for law, _ in net.groups:
        if any(np.ndim(p) > 1 for p in law.params.values()):
            Bp = batch[0]
    kind = np.empty(L, dtype=np.int64)
    par = np.zeros((Bp, L, PARAMETERS))
    for law, index in net.groups:
        name = type(law).__name__
        if name not in LAW_KINDS:
            raise ValueError(f"the compiled methods do not know the law {name}; use method='odeint'")
        kind[index] = LAW_KINDS[name]
        for column, value in enumerate(law.params.values()):
            value = np.asarray(value, dtype=float)
            par[:, index, column] = value if value.ndim < 2 else value.reshape(Bp, -1)
    mass = np.atleast_2d(np.repeat(net.mass, d, axis=-1))
    per_unit_g = np.zeros((*batch, S, d))  # gravity acts on the weight masses, along -axis (the last component)
    per_unit_g[..., -1] = net.weight_mass / net.mass
    gravity = np.atleast_2d(per_unit_g.reshape(*batch, S * d))
    planar = net.positions is not None and d > 1
    rest_vectors = np.asarray(net.rest_vectors, dtype=float) if planar else np.zeros((L, d))
    spans = np.asarray(net.spans, dtype=float) if planar else np.zeros(L)
    prestretch = np.asarray(net.prestretch, dtype=float) if planar else np.zeros(L)
    # The fast path: a chain (Network.is_path) whose link k is the one of site k.
    path = net.is_path and np.array_equal(net.i, np.arange(L))
    ints = np.array([0, d, net.n_coords, int(net.damped), S, L, 0, 0, 0, int(path)], dtype=np.int64)
    return Packed(ints, _empty(2), kernel_array(1.0 / mass), kernel_array(gravity, dtype=float),
                  net.i.astype(np.int64), net.j.astype(np.int64), kind, par, kernel_array(rest_vectors),
                  kernel_array(spans), kernel_array(prestretch), _empty(0, 0), _empty(0),
                  _empty(0))  # fmt: skip


def pack_ring_chain(chain) -> PackedRingChain:
    """The :class:`PackedRingChain` form of a :class:`~ringchain.numerics.RingChain`."""
    ring, N, n = chain.ring, chain.n_rings, chain.ring.n_dof
    coupling = -(ring.inverse_mass @ ring.stiffness).T
    ints = np.array([1, 1, N * n, 0, 0, 0, N, n, int(chain.support == "fixed"), 0], dtype=np.int64)
    return PackedRingChain(ints, np.array([chain.K_c, chain.n]), _empty(1, 0), np.atleast_2d(ring.rigid.astype(float)),
                  _empty(0, dtype=np.int64), _empty(0, dtype=np.int64), _empty(0, dtype=np.int64),
                  _empty(1, 0, PARAMETERS), _empty(0, 1), _empty(0), _empty(0),
                  kernel_array(coupling), kernel_array(ring.inverse_mass[:, 1]),
                  kernel_array(ring.inverse_mass[:, 0]))  # fmt: skip


# -- the laws --------------------------------------------------------------------------------------------------
