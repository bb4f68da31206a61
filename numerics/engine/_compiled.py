"""What every compiled kernel module of the engine shares: the folder of the disk cache and the packed model.

The kernels (:mod:`.kernels`, :mod:`.rings_step`, :mod:`.rings_kernels`, :mod:`.rings_law`) call one another, so
they must agree on one cache folder, keyed on all their sources (:data:`KERNEL_MODULES`), and on the one tuple a
model is packed into (:class:`Packed`; :class:`PackedRingChain` and :class:`PackedRings` for the other two kinds);
they live here so that no kernel module imports another in a circle.
"""

from __future__ import annotations

import os
import tempfile
from typing import NamedTuple

import numpy as np

__all__ = ["CACHE", "KERNEL_MODULES", "Packed", "PackedRingChain", "PackedRings", "jit"]

#: The modules whose compiled kernels call one another (the disk cache is keyed on all their sources).
KERNEL_MODULES = ("_compiled.py", "kernels.py", "rings_step.py", "rings_kernels.py", "rings_law.py", "fields.py")


def _cache_folder() -> str | None:
    """The folder of compiled code, or None where the package's cache is disabled or not writable."""
    from ringchain.theory._codegen import cache_dir

    folder = cache_dir()
    if folder is None:
        return None
    folder = folder / "numba" / _sources_key()
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile(dir=folder):
            pass
    except OSError:
        return None
    return os.fspath(folder)


def _sources_key() -> str:
    """A hash of the sources of every kernel module (:data:`KERNEL_MODULES`): a kernel cached
    on disk is keyed on its own file only, so a change to a kernel it calls in another module must change the
    folder instead."""
    import hashlib

    digest = hashlib.sha256()
    here = os.path.dirname(os.path.abspath(__file__))
    for name in KERNEL_MODULES:
        try:
            with open(os.path.join(here, name), "rb") as handle:
                digest.update(handle.read())
        except OSError:
            digest.update(name.encode())
    return digest.hexdigest()[:16]


#: Where compiled kernels are cached (None: compiled in every process).
CACHE = _cache_folder()


def jit(**options):
    """``numba.njit`` cached on disk in :data:`CACHE` (compiled in every process where it is None), with NumPy's
    error model; Numba reads its cache folder when a kernel is decorated, so the folder is set for that moment
    only."""
    import numba

    def decorate(function):
        previous = numba.config.CACHE_DIR
        if CACHE is not None:
            numba.config.CACHE_DIR = CACHE
        try:
            return numba.njit(cache=CACHE is not None, error_model="numpy", **options)(function)
        finally:
            numba.config.CACHE_DIR = previous

    return decorate


class Packed(NamedTuple):
    """A model as the kernels take it (see the module notes); build it with :func:`pack_network` or
    :func:`pack_ring_chain`."""

    ints: np.ndarray  # [kind (0 network, 1 rings), dim, n_coords, damped, n_sites, n_links, rings, dofs, fixed, path]
    floats: np.ndarray  # [K_c, exponent] of the ring-resolved chain's contact
    inv_mass: np.ndarray  # (Bm, n_coords)
    gravity: np.ndarray  # (Bm, n_coords): gravity's acceleration per unit g; for rings, the rigid mode
    li: np.ndarray  # (L,) int64
    lj: np.ndarray  # (L,) int64, -1 for the support
    kind: np.ndarray  # (L,) int64
    par: np.ndarray  # (Bp, L, PARAMETERS)
    rest_vectors: np.ndarray  # (L, dim): from site i to the link's far end at rest (Network.rest_vectors)
    spans: np.ndarray  # (L,): their lengths (Network.spans)
    prestretch: np.ndarray  # (L,): the links' extensions at rest (Network.prestretch)
    coupling: np.ndarray  # (n, n)
    inv_top: np.ndarray  # (n,)
    inv_bottom: np.ndarray  # (n,)


# The integrators are compiled once per packed type and take the right-hand side by it (kernels._derivative), so
# that a chain's run never compiles the ring-resolved chain or the rigid rings, nor theirs the links' laws.  Numba
# keys its disk cache on the type: each is compiled once.  The two types below have the fields of Packed.

#: A ring-resolved chain packed for the kernels (kind 1): the fields of :class:`Packed`, under a type of its own.
PackedRingChain = NamedTuple("PackedRingChain", list(Packed.__annotations__.items()))

#: Rigid rings in space packed for the kernels (kind 2): the fields of :class:`Packed`, under a type of its own.
PackedRings = NamedTuple("PackedRings", list(Packed.__annotations__.items()))
