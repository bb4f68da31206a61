r"""Compiled kernels of the engine: the right-hand sides of networks and of the ring-resolved chain, an
adaptive Dormand-Prince 5(4) pair with dense output and velocity Verlet, whole time loops in Numba.

The same models as :mod:`ringchain.numerics.engine.network` and :mod:`ringchain.numerics.layouts.ring_chain`, written as
loops over plain arrays (no Python object in the time loop), and the same contract: what
:func:`ringchain.numerics.simulate` calls with ``method="dopri5"`` or ``method="verlet"``.  The NumPy and
SciPy paths stay as the independent reference the tests compare against.

Models.  A model is packed once (:func:`pack_network`, :func:`pack_ring_chain`) into a :class:`Packed`
tuple of arrays of fixed types, whatever its kind, so that every kernel compiles once per process (once
ever, with the disk cache) and not once per chain:

- a network: per link its two sites (``-1`` for the support), its law's kind and parameters (a row of
  ``PARAMETERS`` numbers: K, n, gamma for :class:`~ringchain.numerics.laws.PowerLaw`; K, gamma for
  :class:`~ringchain.numerics.laws.LinearSpring`; gamma for :class:`~ringchain.numerics.laws.Dashpot`; K, delta_y,
  gamma, initial memory for :class:`~ringchain.numerics.laws.Thornton`; K, n, alpha for
  :class:`~ringchain.numerics.laws.HuntCrossley`),
  per site its inverse mass and the acceleration of gravity; in two or three dimensions the links' rest
  vectors (site i to the far end, a periodic image or an anchor), their spans and prestretches;
- the ring-resolved chain: one ring's coupling matrix -M^-1 K, the columns of M^-1 at its two contact
  points, its rigid translation, and the Hertz contact.

A stack of networks (:meth:`~ringchain.numerics.Network.stack`) gives per-member masses and parameters
(a leading axis of length B; length 1 when every member shares them).

Laws with memory.  A network with a :class:`~ringchain.numerics.laws.Thornton` link carries one memory per
link (its largest approach, m) at the end of each run's state, [x, u, W if damped, memory if stateful].
Its derivative is zero, so the Runge-Kutta stages carry it unchanged and a trial stage (or a rejected step)
never writes it; the law reads max(memory, delta), so a stage beyond the memory is on the loading curve.
After each accepted step the memory becomes the largest extension over the step, read from the cubic
through the extensions and rates at both ends (:func:`_remember`: the peak of a step, not only its end,
to fourth order); a sample records the memory its step started from (what the stages used).  Velocity
Verlet updates it after each step from the new positions.  (Memory as an integrated state, dm/dt = the
rate while loading, jumps whenever the approach crosses the memory: rejections at every loading.)

The Runge-Kutta pair.  Dormand and Prince's 5(4) pair with its fourth-order continuous extension
(Hairer, Norsett and Wanner, Solving ODEs I, Sec. II.5-6), first-same-as-last, step-size control
0.9 err^(-1/5) within [0.2, 10].  The error is measured in the max norm over the components,
|err_i| / (atol_i + rtol max(|y_i|, |y_new_i|)): a component whose derivative is exactly zero (a site
at rest with no net force), or a run repeated in a batch, never changes the steps a run takes (an
RMS norm over n components loosens the control by sqrt(n) when most of them are idle).  A member
hanging at rest under gravity is not exactly idle: its rounding-level accelerations, against its own
tiny tolerances, change a shared step slightly (``shared=True``: 601 steps instead of 596 measured).
Each member of a batch takes its own steps, on a pool of threads through one kernel that releases the GIL
(one compiled kernel for one run or many).  The samples are read from the continuous extension.

Velocity Verlet.  The fixed-step scheme of :func:`ringchain.numerics.engine.integrate` (kick-drift-kick in
leapfrog form, samples by cubic Hermite interpolation of the two ends of their step).

Contacts opening and closing.  A contact's force (K delta^n while delta > 0, zero beyond) is not smooth
where delta crosses zero; a step straddling that instant loses the pair's order, its error estimate no
longer measures its error, and the error stops falling with the tolerance (on the paper's chain, 1.8e-3
to 6.8e-4 of the peak from rtol 1e-6 to 1e-8).  So each step ends where a contact opens or closes
(``locate``, the default): once a trial step passes the error test, each contact's extension is followed
on the cubic through its values and rates at both ends, and where one changes sign inside, the step is
retaken to end just past the first change (bisection on the cubic).  The error then falls as a
fifth-order method's (benchmarks/bench_paper_recipe.py).  Thornton's contact is not located yet (its
switch, the zero of the unloading curve, moved with the memory and the step underflowed in a collision).

The disk cache.  Kernels are compiled on first use and cached on disk by Numba in the package's cache
folder (``<ringchain cache>/numba``, :func:`ringchain.theory._codegen.cache_dir`), so a later process
loads them.  Every kernel lives in this one module: Numba keys a cached kernel on its own file, and a
change to a kernel in another module would not invalidate the cache of a kernel calling it.  Where
the folder is disabled or not writable, the kernels are compiled in every process instead (about
the cold compile time stated in benchmarks/bench_kernels.py); a line on stderr says so before a compile.
No module-level value enters a kernel: Numba freezes globals as constants in the compiled code.
"""

from __future__ import annotations

import math

import numba
import numpy as np
from numba.extending import overload

from . import rings_step
from ._compiled import CACHE, Packed, PackedRingChain, PackedRings
from ._kernel_calls import announce_compile, dopri5_tableau, kernel_array, over_threads, verlet_arrays
from .packing import LAW_KINDS, PARAMETERS, pack, pack_network, pack_ring_chain

__all__ = [
    "Packed",
    "PackedRingChain",
    "PackedRings",
    "pack",
    "pack_network",
    "pack_ring_chain",
    "dopri5",
    "verlet",
    "accelerations",
    "CACHE",
    "PARAMETERS",
    "LAW_KINDS",
    "law_force",
    "STATUS",
]

#: Exit codes of the integrators: 0 done; 1 too many steps; 2 a non-finite state; 3 the step underflowed.
STATUS = {1: "too many steps", 2: "the state became non-finite", 3: "the step size fell below the time resolution"}


_previous_cache_dir = numba.config.CACHE_DIR
if CACHE is not None:
    numba.config.CACHE_DIR = CACHE  # read when each kernel below is decorated; restored at the end of the module


def _jit(**options):
    return numba.njit(cache=CACHE is not None, error_model="numpy", **options)


def _inner(**options):
    """A kernel called from other kernels only: no wrapper to call it from Python or C (each cost a
    compile of its arguments' boxing, the packed model's fourteen arrays)."""
    return _jit(no_cpython_wrapper=True, no_cfunc_wrapper=True, **options)


@_jit(inline="always")
def _larger(a, b):
    """max(a, b) as Python's builtin takes it (b if b > a, else a), inlined where it is called: the builtin's
    overload is a kernel of its own, compiled once per type of its arguments."""
    return b if b > a else a


@_jit(inline="always")
def _smaller(a, b):
    """min(a, b) as Python's builtin takes it (b if b < a, else a), inlined (as :func:`_larger`)."""
    return b if b < a else a


@_inner()
def _copy(source, target):
    """target[:] = source, written out (a slice assignment compiles a check of shapes that formats its message:
    seconds of the cold compile)."""
    for c in range(source.size):
        target[c] = source[c]


@_jit(forceinline=True)
def law_force(kind, p0, p1, p2, e, rate, memory):
    """(force, elastic force) of one link, N: the :mod:`ringchain.numerics.laws` of kind ``kind`` (:data:`LAW_KINDS`),
    parameters p0-p2, at extension ``e`` (m) and its rate (m/s); ``memory``: Thornton's largest approach (m)."""
    if kind == 0:  # PowerLaw: [K delta^n + gamma delta_dot]_+ where engaged (K, n, gamma)
        if e <= 0.0:
            return 0.0, 0.0
        elastic = p0 * e * math.sqrt(e) if p1 == 1.5 else p0 * e**p1
        force = elastic + p2 * rate
        return (force if force > 0.0 else 0.0), elastic
    if kind == 1:  # LinearSpring: K delta + gamma delta_dot (K, gamma)
        elastic = p0 * e
        return elastic + p1 * rate, elastic
    if kind == 3:  # Thornton: the memory is the largest approach (K_c, delta_y, gamma)
        return _thornton(p0, p1, p2, e, rate, memory)
    if kind == 4:  # HuntCrossley: [K delta^n (1 + 3/2 alpha delta_dot)]_+ where engaged (K, n, alpha)
        if e <= 0.0:
            return 0.0, 0.0
        elastic = p0 * e * math.sqrt(e) if p1 == 1.5 else p0 * e**p1
        force = elastic * (1.0 + 1.5 * p2 * rate)
        return (force if force > 0.0 else 0.0), elastic
    return p0 * rate, 0.0  # Dashpot (gamma)


@_inner()
def _thornton(K, dy, gamma, e, rate, memory):
    """(force, elastic force) of Thornton's contact (:class:`~ringchain.numerics.laws.Thornton`): with
    dm = max(memory, delta) beyond delta_y, F_m = K sqrt(dy)(3 dm - dy)/2 and w = sqrt(dy)(3 dm - dy)/(2 sqrt(dm)),
    F = F_m (u/w)^(3/2) for u = delta - dm + w > 0; the Hertz curve below delta_y."""
    if e <= 0.0:
        return 0.0, 0.0
    dm = memory if memory > e else e
    if dm <= dy:
        elastic = K * e * math.sqrt(e)
    else:
        F_m = 0.5 * K * math.sqrt(dy) * (3.0 * dm - dy)
        w = 0.5 * math.sqrt(dy) * (3.0 * dm - dy) / math.sqrt(dm)
        u = e - dm + w
        if u <= 0.0:
            return 0.0, 0.0
        elastic = F_m * (u / w) * math.sqrt(u / w)
    force = elastic + gamma * rate
    return (force if force > 0.0 else 0.0), elastic


@_inner()
def _extension(m, k, x, u):
    """(extension, rate) of link k of a packed network at displacements x and velocities u (as the right-hand
    side computes them)."""
    i, j, d = m.li[k], m.lj[k], m.ints[1]
    if d == 1:
        far, far_u = (x[j], u[j]) if j >= 0 else (0.0, 0.0)
        return far - x[i], far_u - u[i]
    length2, stretch, rate = 0.0, 0.0, 0.0
    for c in range(d):
        w = (0.0 if j < 0 else x[j * d + c]) - x[i * d + c]
        length2 += (m.rest_vectors[k, c] + w) ** 2
        stretch += (2.0 * m.rest_vectors[k, c] + w) * w
    length = math.sqrt(length2)
    for c in range(d):
        w = (0.0 if j < 0 else x[j * d + c]) - x[i * d + c]
        rate += ((0.0 if j < 0 else u[j * d + c]) - u[i * d + c]) * (m.rest_vectors[k, c] + w) / length
    return stretch / (length + m.spans[k]) + m.prestretch[k], rate


@_inner()
def _cubic(e0, s0, e1, s1, z):
    """The cubic with values e0, e1 and slopes s0, s1 at 0 and 1, at z."""
    z2 = z * z
    z3 = z2 * z
    return (2 * z3 - 3 * z2 + 1) * e0 + (z3 - 2 * z2 + z) * s0 + (-2 * z3 + 3 * z2) * e1 + (z3 - z2) * s1


@_inner()
def _cubic_peak(e0, s0, e1, s1):
    """Largest value on [0, 1] of the cubic with values e0, e1 and slopes s0, s1 (per unit parameter) at its ends."""
    a, b, c = 6.0 * (e0 - e1) + 3.0 * (s0 + s1), 6.0 * (e1 - e0) - 4.0 * s0 - 2.0 * s1, s0  # p'(s) = a s^2 + b s + c
    peak = _larger(e0, e1)
    disc = b * b - 4.0 * a * c
    roots = (
        (-c / b if b != 0.0 else -1.0, -1.0)
        if a == 0.0
        else (((-b + math.sqrt(disc)) / (2.0 * a), (-b - math.sqrt(disc)) / (2.0 * a)) if disc >= 0.0 else (-1.0, -1.0))
    )
    for z in roots:
        if 0.0 < z < 1.0:
            peak = _larger(peak, _cubic(e0, s0, e1, s1, z))
    return peak


def _remember(m, start, G, value0, rate0, value1, rate1, y_new, h, N, n):
    """After an accepted step to ``y_new`` (the states of the G runs from ``start``), each Thornton link's memory in
    ``y_new`` becomes the largest of its memory and the peak extension over the step (the module notes), from the
    links' extensions and rates at both ends (:func:`_switches`' rows).  Returns whether a memory now exceeds its
    link's extension at the end of the step.  Compiled: chosen by the packed type (no memory but a network's)."""


def _network_remember(m, start, G, value0, rate0, value1, rate1, y_new, h, N, n):
    w = 2 * N + (1 if m.ints[3] else 0)
    changed = False
    for q in range(G):
        o = q * n
        for k in range(n - w):
            if m.kind[k] == 3:
                e1 = value1[q, k]
                peak = _cubic_peak(value0[q, k], h * rate0[q, k], e1, h * rate1[q, k])
                if peak > y_new[o + w + k]:
                    changed = changed or peak > e1  # memory beyond the end's approach: the force at the end changes
                    y_new[o + w + k] = peak
    return changed


def _no_memory(m, start, G, value0, rate0, value1, rate1, y_new, h, N, n):
    return False


def _update_memory(m, x, u, memory):
    """Velocity Verlet's memory after a step: each Thornton link's becomes the larger of it and the link's extension
    at the new positions ``x`` (compiled: chosen by the packed type, as :func:`_remember`)."""


def _network_update_memory(m, x, u, memory):
    for link in range(memory.size):
        if m.kind[link] == 3:
            e, _ = _extension(m, link, x, u)
            memory[link] = _larger(memory[link], e)


# -- right-hand sides ----------------------------------------------------------------------------------------
def _network_accelerations(m, b, g, x, u, out, memory):
    """Accelerations of member ``b`` of a packed network under gravity ``g`` into ``out``; returns the power its
    dashpots take out."""
    d, n, damped = m.ints[1], m.ints[2], m.ints[3] != 0
    bm = b * (m.inv_mass.shape[0] > 1)  # one row shared by every member, or one per member (integers only:
    bp = b * (m.par.shape[0] > 1)  # an index may be unsigned, and b if ... else 0 would unify to a float)
    par, li, lj, kind = m.par[bp], m.li, m.lj, m.kind
    for c in range(n):
        out[c] = 0.0
    power = 0.0
    L = li.size
    path = m.ints[9] != 0  # a chain: link k joins site k to site k + 1, the last one perhaps to the support
    for k in range(L):
        if path:
            i, j = k, (k + 1 if k + 1 < n else -1)
        else:
            i, j = li[k], lj[k]
        length = 1.0
        if d == 1:
            if j >= 0:
                e = x[j] - x[i]
                rate = u[j] - u[i] if damped else 0.0
            else:
                e = -x[i]
                rate = -u[i] if damped else 0.0
        else:
            # The extension as Network.extensions computes it: |b + w| - |b| = (2 b.w + w.w)/(|b + w| + |b|),
            # from the rest vector b and the relative displacement w of the ends, free of the cancellation of
            # two lengths of order |b|, plus the prestretch.
            length2 = 0.0
            stretch = 0.0
            for c in range(d):
                w = (0.0 if j < 0 else x[j * d + c]) - x[i * d + c]
                length2 += (m.rest_vectors[k, c] + w) ** 2
                stretch += (2.0 * m.rest_vectors[k, c] + w) * w
            length = math.sqrt(length2)
            e = stretch / (length + m.spans[k]) + m.prestretch[k]
            rate = 0.0
            if damped:
                for c in range(d):
                    w = (0.0 if j < 0 else x[j * d + c]) - x[i * d + c]
                    du = (0.0 if j < 0 else u[j * d + c]) - u[i * d + c]
                    rate += du * (m.rest_vectors[k, c] + w) / length
        force, elastic = law_force(kind[k], par[k, 0], par[k, 1], par[k, 2], e, rate, memory[k] if memory.size else 0.0)
        if damped:
            power += (force - elastic) * rate
        if d == 1:
            out[i] += force
            if j >= 0:
                out[j] -= force
        else:
            for c in range(d):
                w = (0.0 if j < 0 else x[j * d + c]) - x[i * d + c]
                component = force * (m.rest_vectors[k, c] + w) / length
                out[i * d + c] += component
                if j >= 0:
                    out[j * d + c] -= component
    inv_mass, gravity = m.inv_mass[bm], m.gravity[bm]
    for c in range(n):
        out[c] = out[c] * inv_mass[c] - g * gravity[c]
    return power


def _ring_chain_accelerations(m, b, g, x, u, out, memory):
    """Accelerations of the ring-resolved chain under gravity ``g`` (:meth:`~ringchain.numerics.RingChain.stepper`);
    no dashpot (returns 0.0)."""
    N, n, fixed = m.ints[6], m.ints[7], m.ints[8]
    K_c, exponent = m.floats[0], m.floats[1]
    for r in range(N):
        for a in range(n):
            total = 0.0
            for c in range(n):
                total += x[r * n + c] * m.coupling[c, a]
            out[r * n + a] = total
    for r in range(N):  # the contact above ring r: with ring r + 1, or the support
        if r < N - 1:
            e = x[(r + 1) * n] - x[r * n + 1]
        elif fixed:
            e = -x[r * n + 1]
        else:
            continue
        force = 0.0
        if e > 0.0:
            force = K_c * e * math.sqrt(e) if exponent == 1.5 else K_c * e**exponent
        for a in range(n):
            out[r * n + a] += force * m.inv_top[a]  # pulled up at its top
            if r < N - 1:
                out[(r + 1) * n + a] -= force * m.inv_bottom[a]  # the ring above pulled down at its bottom
    rigid = m.gravity[0]
    for r in range(N):
        for a in range(n):
            out[r * n + a] -= g * rigid[a]
    return 0.0


def _accelerations(m, b, g, x, u, out, memory):
    """Accelerations of member ``b`` of a network or of the ring-resolved chain into ``out``; returns the power its
    dashpots take out.  ``memory`` per link (laws with memory) or empty.  Compiled: chosen by the packed type."""


def _group_derivative(m, start, G, g, y, dy, N, n):
    """dy/dt of the G runs from ``start`` stepped together, their states of length n one after the other in ``y``
    (compiled: chosen by the packed type)."""


def _switches(m, start, G, y, N, n, out_value, out_rate):
    """Each switch (value, rate) of the G runs from ``start`` at their states ``y``, one row per run: zero where a
    contact's force stops being smooth (its extension, as :func:`_extension`); (1, 0) for a smooth law (compiled:
    chosen by the packed type)."""


def _after_step(m, y, G, n):
    """What a model does to the G states of length n in ``y`` after an accepted step (compiled: by type)."""


def _network_group_derivative(m, start, G, g, y, dy, N, n):
    """dy/dt of each state [x (N), u (N), W (dissipated energy, if damped), memory (per link, if stateful)]."""
    w = 2 * N + (1 if m.ints[3] else 0)
    for q in range(G):
        o = q * n
        power = _accelerations(m, start + q, g, y[o : o + N], y[o + N : o + 2 * N], dy[o + N : o + 2 * N],
                               y[o + w : o + n])  # fmt: skip
        for c in range(N):
            dy[o + c] = y[o + N + c]
        if w > 2 * N:
            dy[o + 2 * N] = power
        for c in range(o + w, o + n):
            dy[c] = 0.0  # the memory changes on accepted steps only


def _rings_group_derivative(m, start, G, g, y, dy, N, n):
    for q in range(G):
        rings_step.rings_derivative(m, start + q, g, y[q * n : (q + 1) * n], dy[q * n : (q + 1) * n], N)


def _nothing(m, *args):
    return 0


#: The options of the right-hand sides chosen by type (kernels called from kernels only, as :func:`_inner`).
_INNER = dict(error_model="numpy", no_cpython_wrapper=True, no_cfunc_wrapper=True)


def _packed_type(m):
    return getattr(m, "instance_class", None)


# The right-hand side, the switches and the memory are chosen when a kernel is compiled, by the packed model's type
# (Packed, PackedRingChain, PackedRings), not by its kind code at run time: a chain's integrator holds neither the
# ring-resolved chain nor the rigid rings (they were most of its compile), and theirs none of the links' laws,
# switches or memory.  The chosen function is compiled into the kernel's own call tree, which is kept shallow:
# Numba optimises and generates machine code again for every compiled function at every level of calls above it
# (measured: the cold compile of the paper's chain, 67 s with every kind in one kernel and inlined in Numba's IR,
# 24 s by type, fewer levels less; what it costs now: benchmarks/bench_kernels.py, part (c)).
def _by_type(stub, network, ring_chain=None, rings=None):
    """Compile a call of ``stub`` as ``network``, ``ring_chain`` or ``rings`` by the packed model's type (its first
    argument; ``network`` where the others are not given), a kernel called from kernels only (:func:`_inner`)."""

    def choose(m, *args):
        kind = _packed_type(m)
        return (rings if kind is PackedRings else ring_chain if kind is PackedRingChain else None) or network

    overload(stub, jit_options=_INNER, strict=False)(choose)


@_jit()
def _accelerations_of(m, b, g, x, u, out, memory):
    return _accelerations(m, b, g, x, u, out, memory)


def accelerations(packed: Packed, x, u=None, g=9.80665, member=0, memory=None) -> np.ndarray:
    """Accelerations of one state (m/s^2), for tests: the compiled right-hand side against the NumPy one
    (``memory``: the largest approach of each link, m, for laws with memory; read, never written)."""
    x = kernel_array(x, dtype=float)
    u = np.zeros_like(x) if u is None else kernel_array(u, dtype=float)
    memory = np.zeros(0) if memory is None else kernel_array(memory, dtype=float)
    out = np.empty_like(x)
    _accelerations_of(packed, member, float(g), x, u, out, memory)
    return out


# -- contacts opening and closing --------------------------------------------------------------------------------
@_inner()
def _first_zero(e0, s0, e1, s1, start, end):
    """The first change of sign in (start, end) of the cubic with values e0, e1 and slopes s0, s1 at 0 and 1
    (found on its monotone pieces by bisection; the point just past it), or 2.0 if it keeps its sign there."""
    a, b, c = 6.0 * (e0 - e1) + 3.0 * (s0 + s1), 6.0 * (e1 - e0) - 4.0 * s0 - 2.0 * s1, s0  # p'(z) = a z^2 + b z + c
    cut1, cut2 = end, end  # the turning points inside (start, end), in order
    if a != 0.0:
        disc = b * b - 4.0 * a * c
        if disc > 0.0:
            r1, r2 = (-b - math.sqrt(disc)) / (2.0 * a), (-b + math.sqrt(disc)) / (2.0 * a)
            cut1, cut2 = _smaller(r1, r2), _larger(r1, r2)
    elif b != 0.0:
        cut1 = -c / b
    lo = start
    v_lo = _cubic(e0, s0, e1, s1, lo)
    for piece in range(3):
        hi = cut1 if piece == 0 else (cut2 if piece == 1 else end)
        if hi <= lo:
            continue
        hi = _smaller(hi, end)
        v_hi = _cubic(e0, s0, e1, s1, hi)
        if (v_lo > 0.0) != (v_hi > 0.0):
            for _ in range(60):  # bisection on a monotone piece, to the last bits of z
                mid = 0.5 * (lo + hi)
                v_mid = _cubic(e0, s0, e1, s1, mid)
                if (v_mid > 0.0) == (v_lo > 0.0):
                    lo, v_lo = mid, v_mid
                else:
                    hi = mid
                if hi - lo <= 1e-15:
                    break
            return hi
        lo, v_lo = hi, v_hi
    return 2.0


def _network_switches(m, start, G, y, N, n, out_value, out_rate):
    """The switches of a network's links: the extension of a power law, Hunt-Crossley's and Thornton's (read by
    :func:`_remember`; not located yet: see the notes).  Written out: a call per link passing the packed model
    costs more."""
    S, d = out_value.shape[1], m.ints[1]
    for q in range(G):
        o, v = q * n, q * n + N  # displacements and velocities of member q
        for k in range(S):
            e, rate = 1.0, 0.0
            if m.kind[k] == 0 or m.kind[k] == 3 or m.kind[k] == 4:
                i, j = m.li[k], m.lj[k]
                if d == 1:
                    e = (y[o + j] if j >= 0 else 0.0) - y[o + i]
                    rate = (y[v + j] if j >= 0 else 0.0) - y[v + i]
                else:
                    length2, stretch, rate = 0.0, 0.0, 0.0
                    for c in range(d):
                        gap = (0.0 if j < 0 else y[o + j * d + c]) - y[o + i * d + c]
                        length2 += (m.rest_vectors[k, c] + gap) ** 2
                        stretch += (2.0 * m.rest_vectors[k, c] + gap) * gap
                    length = math.sqrt(length2)
                    for c in range(d):
                        gap = (0.0 if j < 0 else y[o + j * d + c]) - y[o + i * d + c]
                        du = (0.0 if j < 0 else y[v + j * d + c]) - y[v + i * d + c]
                        rate += du * (m.rest_vectors[k, c] + gap) / length
                    e = stretch / (length + m.spans[k]) + m.prestretch[k]
            out_value[q, k], out_rate[q, k] = e, rate


def _ring_chain_switches(m, start, G, y, N, n, out_value, out_rate):
    """The switches of the ring-resolved chain: the contact above ring k, with ring k + 1 or the support."""
    S, dofs = out_value.shape[1], m.ints[7]
    for q in range(G):
        o = q * n
        for k in range(S):
            e, rate = 1.0, 0.0
            top = o + k * dofs + 1
            if k < S - 1:
                e, rate = y[top + dofs - 1] - y[top], y[top + dofs - 1 + N] - y[top + N]
            elif m.ints[8]:
                e, rate = -y[top], -y[top + N]
            out_value[q, k], out_rate[q, k] = e, rate


@_inner()
def _first_switch(value0, rate0, value1, rate1, h, floor, kinds):
    """Where in a step of length ``h`` a switch first changes sign (on the cubic through the values and rates at
    its ends; within 1e-7 of an end: at that end; not within ``floor`` of zero), a fraction of it; 2.0: none.
    ``kinds``: the links' laws (a Thornton link's is not located), or empty."""
    first = 2.0
    for q in range(value0.shape[0]):
        for k in range(value0.shape[1]):
            if k < kinds.size and kinds[k] == 3:
                continue
            e0, e1 = value0[q, k], value1[q, k]
            s0, s1 = h * rate0[q, k], h * rate1[q, k]
            slope = e1 - e0  # p(z) = (1 - z) e0 + z e1 + z (1 - z) ((1 - z)(s0 - slope) - z (s1 - slope)):
            bend = 0.25 * _larger(abs(s0 - slope), abs(s1 - slope))
            if (e0 > 0.0) == (e1 > 0.0) and _smaller(abs(e0), abs(e1)) > bend:
                continue  # it stays within max|s - slope|/4 of the chord, which keeps its sign: no zero
            if _larger(abs(e0), abs(e1)) + bend <= floor:
                continue  # it stays within the displacements' tolerance of zero (rounding at rest): no matter
            first = _smaller(first, _first_zero(e0, s0, e1, s1, 1e-7, 1.0 - 1e-7))
    return first


# The right-hand sides and what else depends on the model, by its type (_by_type).
_by_type(_accelerations, _network_accelerations, ring_chain=_ring_chain_accelerations)
_by_type(_group_derivative, _network_group_derivative, rings=_rings_group_derivative)
_by_type(_after_step, _nothing, rings=rings_step.normalise.py_func)
_by_type(_switches, _network_switches, ring_chain=_ring_chain_switches, rings=_nothing)
_by_type(_remember, _network_remember, ring_chain=_no_memory, rings=_no_memory)
_by_type(_update_memory, _network_update_memory, ring_chain=_nothing, rings=_nothing)


# -- Dormand-Prince 5(4) -----------------------------------------------------------------------------------------
@_inner()
def _error_norm(err, y, y_new, atol, rtol):
    worst = 0.0
    for c in range(err.size):
        scale = atol[c] + rtol * _larger(abs(y[c]), abs(y_new[c]))
        ratio = abs(err[c]) / scale
        if not ratio <= worst:  # NaN too
            worst = ratio
    return worst


@_inner()
def _finite(y):
    for c in range(y.size):
        if not math.isfinite(y[c]):
            return False
    return True


@_jit(nogil=True)
def _dopri5_runs(m, g, y0, t_eval, rtol, atol, keep, N, out_x, out_u, out_w, max_steps, status, stats, final,
                 out_m, tableau, first, last, shared, locate):  # fmt: skip
    """Runs ``first`` to ``last`` (excluded) of the states ``y0`` (B, n), each with its own steps, or all of them
    with one step size, the error measured over all of them (``shared``); without the GIL, so that threads can
    take disjoint ranges of runs.

    ``atol`` is (B, n); ``out_x``, ``out_u`` (B, T, K) and ``out_w`` (B, T) are filled at the runs' rows, ``out_m``
    (B, T, links) with the memory of laws that have one; ``status`` (B,), ``stats`` (B, 4: evaluations, steps,
    rejections, steps cut at a contact) and ``final`` (B, n) too.  ``locate``: steps end where a contact opens
    or closes (the module notes).  (One kernel, no call level between it and the right-hand side: see
    _group_derivative.)
    """
    group = _larger(1, last - first) if shared else 1
    n = y0.shape[1]
    for start in range(first, last, group):
        G = _smaller(group, last - start)
        size = G * n
        # One allocation of one type for every work array (each type of np.empty's arguments is a compile of its own).
        work = np.empty((12, size))
        stages, y_stage, y_new, err, y, tolerance = work[0:7], work[7], work[8], work[9], work[10], work[11]
        k1, k2, k3, k4, k5, k6, k7 = stages[0], stages[1], stages[2], stages[3], stages[4], stages[5], stages[6]
        for q in range(G):
            for c in range(n):
                y[q * n + c], tolerance[q * n + c] = y0[start + q, c], atol[start + q, c]
        T = t_eval.size
        t_end = t_eval[T - 1]
        t = 0.0
        j = 0
        damped = m.ints[3] != 0
        w = 2 * N + (1 if damped else 0)
        K = keep.size
        while j < T and t_eval[j] <= 0.0:  # samples at the start
            for q in range(G):
                b, o = start + q, q * n
                for c in range(K):
                    out_x[b, j, c], out_u[b, j, c] = y[o + keep[c]], y[o + N + keep[c]]
                out_w[b, j] = y[o + 2 * N] if damped else 0.0
                for c in range(n - w):
                    out_m[b, j, c] = y[o + w + c]
            j += 1
        _group_derivative(m, start, G, g, y, k1, N, n)
        evaluations = 1
        code, steps, rejections, cuts = 0, 0, 0, 0
        if j == T:
            t = t_end  # every sample at the start: no step to take
        # The switches, where contacts are located or a memory reads the extensions (rows of _switches).
        S = 0 if not (locate or n > w) else (m.li.size if m.ints[0] == 0 else (m.ints[6] if m.ints[0] == 1 else 0))
        switches = np.empty((4 * G, S))
        value0, rate0, value1, rate1 = switches[0:G], switches[G : 2 * G], switches[2 * G : 3 * G], switches[3 * G :]
        if S:
            _switches(m, start, G, y, N, n, value0, rate0)
        floor = tolerance[0]  # a switch within the displacements' absolute tolerance of zero is not located
        for c in range(N):
            floor = _smaller(floor, tolerance[c])
        cuts = 0
        h_after = 0.0  # the step a cut step's first trial proposed for after it (0: the last trial was not cut)
        # Guards (without them a sheet struck at a point underflowed its step): at most 3 cuts of one step, and a
        # step that starts where the last one was cut steps over a switch in its first 1 % (the same contact
        # grazing back across zero: cut after cut at the start, the steps shrank to nothing).
        tries = 0
        after_cut = False
        h = 0.0
        if j < T:
            # Initial step (Hairer's HINIT): the first-derivative estimate, then a second-order correction.
            d0, d1 = 0.0, 0.0
            for c in range(size):
                scale = tolerance[c] + rtol * abs(y[c])
                d0 = _larger(d0, abs(y[c]) / scale)
                d1 = _larger(d1, abs(k1[c]) / scale)
            h = 1e-6 * t_end if (d0 < 1e-5 or d1 < 1e-5) else 0.01 * d0 / d1
            h = _smaller(h, t_end)
            for c in range(size):
                y_stage[c] = y[c] + h * k1[c]
            _group_derivative(m, start, G, g, y_stage, k2, N, n)
            evaluations += 1
            d2 = 0.0
            for c in range(size):
                scale = tolerance[c] + rtol * abs(y[c])
                d2 = _larger(d2, abs(k2[c] - k1[c]) / scale / h)
            h1 = _larger(1e-6 * h, 1e-3 * h) if _larger(d1, d2) <= 1e-15 else (0.01 / _larger(d1, d2)) ** 0.2
            h = _smaller(_smaller(100.0 * h, h1), t_end)
        rejected_last = False
        while t < t_end:
            if steps + rejections >= max_steps:
                code = 1
                break
            if t + h > t_end:
                h = t_end - t
            if h <= 1e-14 * _larger(abs(t), t_end):
                code = 3
                break
            for s in range(1, 7):  # the stages after the first; the last one at the new state (first same as last)
                target = y_new if s == 6 else y_stage
                for c in range(size):
                    total = 0.0
                    for r in range(s):
                        total += tableau[s, r] * stages[r, c]
                    target[c] = y[c] + h * total
                _group_derivative(m, start, G, g, target, stages[s], N, n)
            evaluations += 6
            for c in range(size):
                err[c] = h * (71.0 / 57600.0 * k1[c] - 71.0 / 16695.0 * k3[c] + 71.0 / 1920.0 * k4[c]
                              - 17253.0 / 339200.0 * k5[c] + 22.0 / 525.0 * k6[c] - 1.0 / 40.0 * k7[c])  # fmt: skip
            error = _error_norm(err, y, y_new, tolerance, rtol)
            if not math.isfinite(error):
                h *= 0.2
                rejections += 1
                rejected_last = True
                continue
            factor = 0.9 * error**-0.2 if error > 0.0 else 10.0
            if error <= 1.0 and S:
                _switches(m, start, G, y_new, N, n, value1, rate1)
                z = _first_switch(value0, rate0, value1, rate1, h, floor, m.kind) if locate else 2.0
                if (0.01 if after_cut else 0.0) < z < (0.99 if h_after > 0.0 else 1.0) and tries < 3:
                    if h_after == 0.0:
                        h_after = h * _smaller(1.0, _larger(0.2, factor))
                    h *= z
                    cuts += 1
                    tries += 1
                    continue
            if error <= 1.0:
                steps += 1
                t_new = t + h
                # Samples in (t, t + h]: the continuous extension of the pair (Hairer's contd5).
                while j < T and t_eval[j] <= t_new * (1.0 + 1e-15):
                    theta = (t_eval[j] - t) / h
                    theta1 = 1.0 - theta
                    for q in range(G):
                        b, o = start + q, q * n
                        for c in range(2 * K + (1 if damped else 0)):
                            if c < K:
                                r = o + keep[c]
                            elif c < 2 * K:
                                r = o + N + keep[c - K]
                            else:
                                r = o + 2 * N
                            dy = y_new[r] - y[r]
                            bspl = h * k1[r] - dy
                            r4 = dy - h * k7[r] - bspl
                            r5 = (-12715105075.0 / 11282082432.0 * k1[r] + 87487479700.0 / 32700410799.0 * k3[r]
                                  - 10690763975.0 / 1880347072.0 * k4[r])  # fmt: skip
                            r5 = r5 + 701980252875.0 / 199316789632.0 * k5[r]  # the sum in its order
                            r5 = r5 - 1453857185.0 / 822651844.0 * k6[r]
                            r5 = h * (r5 + 69997945.0 / 29380423.0 * k7[r])
                            value = y[r] + theta * (dy + theta1 * (bspl + theta * (r4 + theta1 * r5)))
                            if c < K:
                                out_x[b, j, c] = value
                            elif c < 2 * K:
                                out_u[b, j, c - K] = value
                            else:
                                out_w[b, j] = value
                        for c in range(n - w):
                            out_m[b, j, c] = y[o + w + c]  # the memory the step started from (what its stages used)
                    j += 1
                # A peak inside the step: the new memory changes the force at y_new (first same as last).
                if n > w and _remember(m, start, G, value0, rate0, value1, rate1, y_new, h, N, n):
                    _group_derivative(m, start, G, g, y_new, k7, N, n)
                    evaluations += 1
                _after_step(m, y_new, G, n)
                for c in range(size):
                    y[c] = y_new[c]
                    k1[c] = k7[c]  # first same as last
                t = t_new
                if rejected_last:
                    factor = _smaller(factor, 1.0)
                rejected_last = False
                h *= _smaller(10.0, _larger(0.2, factor))
                tries = 0
                after_cut = h_after > 0.0
                if h_after > 0.0:  # a step cut at a contact: the next one as its first trial proposed
                    h = _larger(h, h_after)
                    h_after = 0.0
                if S:
                    value0, rate0, value1, rate1 = value1, rate1, value0, rate0  # the new step starts where this ended
                if not _finite(y):
                    code = 2
                    break
            else:
                rejections += 1
                rejected_last = True
                h *= _larger(0.2, factor)
        for q in range(G):
            b = start + q
            status[b], stats[b, 0], stats[b, 1], stats[b, 2], stats[b, 3] = code, evaluations, steps, rejections, cuts
            _copy(y[q * n : (q + 1) * n], final[b])


def dopri5(
    packed: Packed, y0, t_eval, rtol, atol, keep, g, *, max_steps=10_000_000, parallel=None, shared=False, locate=True
):
    """Integrate B runs (rows of ``y0``, each [x, u, W if damped, memory per link if stateful]) over ``t_eval``
    with the 5(4) pair.

    Returns x and u of the coordinates ``keep`` (B, T, K), W (B, T), the memory (B, T, links; links 0 without
    memory), the final states (B, n), the exit status of each run (0 done, :data:`STATUS` otherwise) and its
    counts (evaluations, accepted and rejected steps, trial steps cut where a contact opens or closes), shape
    (B, 4).  ``atol`` has one row per run.  Each run takes its own steps, on a pool of threads when
    ``parallel`` (default: more than one run); ``shared``: the runs take one step size, the error measured
    over all of them (forward differences between runs then share their steps).  ``locate``: each step ends
    where a contact opens or closes (the module notes); False steps over them, as a plain pair does.
    """
    y0 = kernel_array(y0, dtype=float)
    B = y0.shape[0]
    T, K = t_eval.size, keep.size
    N = int(packed.ints[2])
    out_x, out_u, out_w = np.empty((B, T, K)), np.empty((B, T, K)), np.zeros((B, T))
    out_m = np.zeros((B, T, y0.shape[1] - 2 * N - int(packed.ints[3] != 0)))
    status, stats, final = np.zeros(B, dtype=np.int64), np.zeros((B, 4), dtype=np.int64), np.empty_like(y0)
    args = (packed, float(g), y0, kernel_array(t_eval, dtype=float), float(rtol),
            kernel_array(atol, dtype=float), kernel_array(keep, dtype=np.int64), N, out_x, out_u, out_w,
            int(max_steps), status, stats, final, out_m, dopri5_tableau())  # fmt: skip
    announce_compile(_dopri5_runs, "dopri5", CACHE, (*args, 0, B, bool(shared), bool(locate)))
    if shared:
        _dopri5_runs(*args, 0, B, True, bool(locate))
    else:
        over_threads(lambda *a: _dopri5_runs(*a, False, bool(locate)), B, B > 1 if parallel is None else parallel,
                      *args)  # fmt: skip
    return out_x, out_u, out_w, out_m, final, status, stats


# -- velocity Verlet -----------------------------------------------------------------------------------------------
@_jit(nogil=True)
def _verlet_runs(m, g, x0, u0, t_eval, n_steps, dt, keep, out_x, out_u, status, final_x, final_u, memory, out_m, first,
                 last):  # fmt: skip
    """Runs ``first`` to ``last`` (excluded), one after the other, without the GIL (one kernel, as dopri5's)."""
    N = x0.shape[1]
    half = 0.5 * dt
    T = t_eval.size
    for b in range(first, last):
        x, u_half, a = x0[b].copy(), np.empty(N), np.empty(N)
        u0b, xs, us, mem, ms = u0[b], out_x[b], out_u[b], memory[b], out_m[b]
        x_prev, u_prev = np.empty(keep.size), np.empty(keep.size)
        _accelerations(m, b, g, x, u0b, a, mem)
        for c in range(N):
            u_half[c] = u0b[c] + half * a[c]
        j = 0
        while j < T and t_eval[j] / dt - 1e-9 <= 0.0:  # samples at the start (step "-1")
            for c in range(keep.size):
                xs[j, c], us[j, c] = x[keep[c]], u0b[keep[c]]
            _copy(mem, ms[j])
            j += 1
        code = 0
        for k in range(n_steps):
            sampling = j < T and math.ceil(t_eval[j] / dt - 1e-9) - 1 == k
            if sampling:
                for c in range(keep.size):
                    x_prev[c] = x[keep[c]]
                    u_prev[c] = u_half[keep[c]] - half * a[keep[c]]
            for c in range(N):
                x[c] += dt * u_half[c]
            _accelerations(m, b, g, x, u_half, a, mem)  # undamped: the velocities are not read
            while j < T and math.ceil(t_eval[j] / dt - 1e-9) - 1 == k:
                s = t_eval[j] / dt - k
                h00, h10, h01, h11 = 2 * s**3 - 3 * s**2 + 1, s**3 - 2 * s**2 + s, -2 * s**3 + 3 * s**2, s**3 - s**2
                d00, d10, d01, d11 = 6 * s**2 - 6 * s, 3 * s**2 - 4 * s + 1, -6 * s**2 + 6 * s, 3 * s**2 - 2 * s
                for c in range(keep.size):
                    q = keep[c]
                    u_now = u_half[q] + half * a[q]
                    xs[j, c] = h00 * x_prev[c] + h10 * dt * u_prev[c] + h01 * x[q] + h11 * dt * u_now
                    us[j, c] = (d00 * x_prev[c] + d01 * x[q]) / dt + d10 * u_prev[c] + d11 * u_now
                _copy(mem, ms[j])
                j += 1
            _update_memory(m, x, u_half, mem)  # the memory after the step, from the new positions
            for c in range(N):
                u_half[c] += dt * a[c]
            if not math.isfinite(x[0] + u_half[0]):
                code = 2
                break
        if code == 0:  # the velocities at the end, in step with the positions
            for c in range(N):
                u_half[c] -= half * a[c]
            if not _finite(x) or not _finite(u_half):
                code = 2
        status[b] = code
        _copy(x, final_x[b])
        _copy(u_half, final_u[b])


def verlet(packed: Packed, x0, u0, t_eval, t_end, dt, keep, g, *, parallel=None, memory=None):
    """Velocity Verlet over ``t_eval`` (steps of ``t_end``/ceil(t_end/dt)): x and u of ``keep`` (B, T, K), the
    final x and u (B, n), the exit status of each run and the step taken; with ``memory`` (B, links: laws with
    memory) also the memory at the samples (B, T, links) and at the end (B, links)."""
    if packed.ints[0] == 2:  # rigid rings: their splitting scheme
        return rings_step.verlet_rings(packed, x0, u0, t_eval, t_end, dt, keep, g)
    x0, u0, n_steps, dt, out_x, out_u, status, final_x, final_u = verlet_arrays(x0, u0, t_eval, t_end, dt, keep)
    B, T = x0.shape[0], t_eval.size
    stateful = memory is not None
    memory = np.array(memory if stateful else np.zeros((B, 0)), dtype=float)  # a copy: the kernel updates it
    out_m = np.zeros((B, T, memory.shape[1]))
    args = (
        packed,
        float(g),
        x0,
        u0,
        kernel_array(t_eval, dtype=float),
        int(n_steps),
        float(dt),
        kernel_array(keep, dtype=np.int64),
        out_x,
        out_u,
        status,
        final_x,
        final_u,
        memory,
        out_m,
    )
    announce_compile(_verlet_runs, "verlet", CACHE, (*args, 0, B))
    over_threads(_verlet_runs, B, B > 1 if parallel is None else parallel, *args)
    if stateful:
        return out_x, out_u, final_x, final_u, status, dt, n_steps, out_m, memory
    return out_x, out_u, final_x, final_u, status, dt, n_steps


numba.config.CACHE_DIR = _previous_cache_dir
