"""How the compiled kernels are called: on a pool of threads, and with a word on stderr before a long compile.

Plain Python beside :mod:`ringchain.numerics.engine.kernels` (no kernel lives here: Numba keys a cached kernel on
its own module's file).

- :func:`over_threads` calls a kernel that releases the GIL over ranges of runs on a pool of threads (one
  compiled kernel serves one run or many: no parallel variant to compile).
- :func:`dopri5_tableau`: the Runge-Kutta pair's coefficients, an argument of its kernel.
- :func:`announce_compile` prints one line on stderr before a kernel is compiled rather than loaded from
  the disk cache: ``ringchain: compiling the integrator for this machine, once: about N s; cached in ...``.
  N is the compile time of that kernel measured on a quiet two-core machine (:data:`COMPILE_SECONDS`),
  scaled by the load average per core when the machine is busier.  It then compiles the kernel under a lock on a
  file of the cache folder: processes that start together on an empty cache (a pool's workers, the pages of a book,
  the workers of a test session) would each compile the same kernel at once; the second one waits for the first,
  then loads its kernel from the disk cache (a second or so, against 10-20 s of compiling).
"""

from __future__ import annotations

import contextlib
import functools
import gc
import itertools
import math
import os
import sys

import numpy as np

#: Seconds to compile each kernel family for each type of packed model (the paper's chain, a ring-resolved chain of
#: five rings, one rigid ring) on a two-core machine: CPU time of the compile in a fresh process, measured at a
#: load of 3 (each type is a compile of its own); the notice scales them by the load.
COMPILE_SECONDS = {
    ("dopri5", "Packed"): 16.0,
    ("dopri5", "PackedRingChain"): 13.0,
    ("dopri5", "PackedRings"): 20.0,
    ("verlet", "Packed"): 9.0,
    ("verlet", "PackedRingChain"): 5.0,
    ("verlet", "PackedRings"): 8.0,
}

_announced: set = set()

#: (dispatcher, :func:`fingerprint` of a call's arguments) of the calls whose kernel was found loaded.
_ready: set = set()


def threads() -> int:
    """Threads the kernels may use: Numba's setting (the cores, or ``NUMBA_NUM_THREADS``)."""
    import numba

    return max(1, int(numba.config.NUMBA_NUM_THREADS))


def over_threads(kernel, B, parallel, *args):
    """Call ``kernel(*args, first, last)`` over the runs 0 to B: in ranges on a pool of threads when
    ``parallel`` (the kernel releases the GIL; a few ranges per thread, so that a slow run does not hold
    the others), else at once."""
    count = min(threads(), B) if parallel else 1
    if count <= 1:
        kernel(*args, 0, B)
        return
    from concurrent.futures import ThreadPoolExecutor

    edges = np.linspace(0, B, min(B, 4 * count) + 1).round().astype(int)
    ranges = [(int(a), int(b)) for a, b in itertools.pairwise(edges) if b > a]
    with ThreadPoolExecutor(count) as pool:
        for done in [pool.submit(kernel, *args, a, b) for a, b in ranges]:
            done.result()


def kernel_array(a, dtype=float) -> np.ndarray:
    """``a`` as a C-contiguous, writable array of ``dtype`` for a kernel's argument (copied only where it is not one
    already).  Numba compiles a kernel once per type of its arguments, and a read-only array (a cached table, a
    broadcast, a frozen result) is another type: one read-only argument compiles the whole integrator again (once
    every run of the suite did, for a read-only ``t_eval`` and the rings' read-only table)."""
    return np.require(a, dtype=dtype, requirements=("C", "W"))


def verlet_arrays(x0, u0, t_eval, t_end, dt, keep):
    """What a fixed-step run of B runs (rows of ``x0``, ``u0``) over ``t_eval`` starts from: x0, u0 as contiguous
    floats, the number of steps and the step (``t_end`` in ceil(t_end/dt) equal steps, s), and the outputs to fill:
    x and u of ``keep`` (B, T, K), the exit status (B,), the final x and u (B, n)."""
    x0 = kernel_array(x0)
    u0 = kernel_array(u0)
    B = x0.shape[0]
    n_steps = max(1, math.ceil(t_end / dt))
    T, K = t_eval.size, keep.size
    out_x, out_u = np.empty((B, T, K)), np.empty((B, T, K))
    status, final_x, final_u = np.zeros(B, dtype=np.int64), np.empty_like(x0), np.empty_like(u0)
    return x0, u0, n_steps, t_end / n_steps, out_x, out_u, status, final_x, final_u


@functools.cache
def dopri5_tableau() -> np.ndarray:
    """Dormand and Prince's coefficients a_sr of stage s from stage r, the last row the fifth-order weights (made here
    and passed to the kernel: no kernel of its own to compile, no module-level value in a kernel).  Made once; the
    kernel only reads it."""
    a = np.zeros((7, 6))
    a[1, 0] = 0.2
    a[2, 0], a[2, 1] = 3.0 / 40.0, 9.0 / 40.0
    a[3, 0], a[3, 1], a[3, 2] = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
    a[4, 0], a[4, 1], a[4, 2], a[4, 3] = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
    a[5, 0], a[5, 1], a[5, 2], a[5, 3], a[5, 4] = (9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0,
                                                   -5103.0 / 18656.0)  # fmt: skip
    a[6, 0], a[6, 2], a[6, 3], a[6, 4], a[6, 5] = (35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0,
                                                   11.0 / 84.0)  # fmt: skip
    return a


def fingerprint(value):
    """What Numba's type of ``value`` depends on, read without Numba (a tuple, hashable), or None where it cannot
    tell: an array's class, dtype, dimensions, layout (C, F or any), whether it is writable and aligned; a tuple's
    type and its items'; the type of a float or a bool; an int's type and whether it fits in int64."""
    if isinstance(value, np.ndarray):
        flags = value.flags
        return (type(value), value.dtype, value.ndim, flags.c_contiguous, flags.f_contiguous, flags.writeable,
                flags.aligned)  # fmt: skip
    if isinstance(value, tuple):
        items = tuple(fingerprint(item) for item in value)
        return None if None in items else (type(value), items)
    if isinstance(value, bool | float | np.bool_ | np.floating):
        return type(value)
    if isinstance(value, int | np.integer):
        return type(value), -(2**63) <= int(value) < 2**63
    return None


def signature_of(args) -> tuple:
    """The Numba types of a kernel call's arguments: the key of its compiled version."""
    import numba

    return tuple(numba.typeof(a) for a in args)


def will_compile(dispatcher, args=None) -> bool:
    """Whether calling a Numba ``dispatcher`` with ``args`` compiles it: no version for their types compiled in
    this process and none in its disk cache (a cache written by another version of the kernels' module is
    stale).  Without ``args``: whether it has no version at all."""
    signature = None if args is None else signature_of(args)
    if signature is None and dispatcher.signatures:
        return False
    if signature is not None and signature in dispatcher.overloads:
        return False
    cache = getattr(dispatcher, "_cache", None)
    try:
        index = cache._cache_file._load_index()
    except (AttributeError, OSError, EOFError, ValueError):  # no disk cache, or one Numba cannot read
        return True
    return not index if signature is None else not any(key[0] == signature for key in index)


def load_factor() -> float:
    """How much slower than a quiet machine this one is now: the load average per core, at least 1."""
    try:
        load = os.getloadavg()[0] / (os.cpu_count() or 1)
    except OSError:  # no load average on this platform
        load = 1.0
    return max(1.0, load)


def compile_estimate(family: str, model: str = "Packed") -> float:
    """Seconds a compile of ``family`` ("dopri5", "verlet") for a packed ``model`` (the name of its type) takes on
    this machine now: the measured figure (of a network's where the type is not listed) times :func:`load_factor`."""
    return COMPILE_SECONDS.get((family, model), COMPILE_SECONDS[family, "Packed"]) * load_factor()


def compiled() -> int:
    """How many kernels this process has compiled (not loaded from the disk cache) so far, one per family
    (``"dopri5"``, ``"verlet"``) and kind of model."""
    return len(_announced)


def announce_compile(dispatcher, family: str, folder, args=None) -> None:
    """One line on stderr when ``dispatcher`` is about to be compiled for ``args`` (once per family, kind of
    model and process: each packed type is compiled on its own).

    A call whose arguments have the :func:`fingerprint` of one already found loaded returns at once: Numba's
    types of the arguments (:func:`signature_of`) cost some 10 ms a call of a chain's packed model, as much as a
    short run (a trace fit makes some twenty)."""
    ready = fingerprint(args)
    if ready is not None and (dispatcher, ready) in _ready:
        return
    key = (family, type(args[0]).__name__ if args else None)
    if key in _announced:
        return
    if not will_compile(dispatcher, args):
        if args is not None:
            load_cached(dispatcher, args)
            if ready is not None:
                _ready.add((dispatcher, ready))
        return
    _announced.add(key)
    where = f"cached in {folder}" if folder else "not cached: the cache folder is disabled or not writable"
    notify(f"ringchain: compiling the integrator for this machine, once: about {compile_estimate(*key):.0f} s; "
           f"{where}")  # fmt: skip
    if folder and args is not None:
        compile_once(dispatcher, args, folder)


@contextlib.contextmanager
def collector_paused():
    """Python's garbage collector paused for the block: Numba's start-up and the load of a cached kernel make
    some hundred thousand objects that live on, and the collector would walk them again and again (measured:
    0.13-0.32 s of the 2 s of CPU of a warm ``ringchain simulate``).  Not for a compile: the objects it makes die
    with it, and paused, its peak memory grows (250 to 297 MB for the paper's chain)."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def load_cached(dispatcher, args) -> None:
    """Load ``dispatcher``'s version for the types of ``args`` from the disk cache (or find it loaded), the collector
    paused (:func:`collector_paused`); the call that follows then runs it at once."""
    signature = signature_of(args)
    if signature not in dispatcher.overloads:
        with collector_paused():
            dispatcher.compile(signature)


def compile_once(dispatcher, args, folder) -> None:
    """Compile ``dispatcher`` for the types of ``args`` holding an exclusive lock on a file of the cache
    ``folder``, so that no two processes compile one kernel at once: a process that waited finds the kernel in the
    disk cache and loads it (Numba's ``compile`` reads the cache first).  Without locks on this platform (no
    ``fcntl``), or with a folder where no lock file can be made, it compiles as the call would."""
    signature = signature_of(args)
    try:
        import fcntl

        handle = open(os.path.join(folder, f"{dispatcher.py_func.__name__}.lock"), "a")
    except (ImportError, OSError):
        dispatcher.compile(signature)
        return
    with handle:
        fcntl.flock(handle, fcntl.LOCK_EX)
        try:
            dispatcher.compile(signature)
        finally:
            fcntl.flock(handle, fcntl.LOCK_UN)


def notify(line: str) -> None:
    """Print ``line`` on stderr at once: the package's notices of what it does (a compile, where a job runs), not
    results.  ``RINGCHAIN_NOTICES=0`` in the environment silences them (the book's build sets it: a page's stderr
    is an error there)."""
    if os.environ.get("RINGCHAIN_NOTICES", "1").strip() != "0":
        print(line, file=sys.stderr, flush=True)
