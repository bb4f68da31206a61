r"""Contact laws of the network engine: small vectorised objects with one contract.

A law gives the force carried by a set of links from their extensions (and, if it has a
dashpot, from the rates of the extensions).  Tension is positive (ARCHITECTURE.md): the
extension delta of a link is the growth of the distance between its two sites, and a
positive force pulls them together.  Every parameter is one number (the same for every
link of the set) or an array with one value per link (the last axis); a stack of several
networks of one layout (:meth:`ringchain.numerics.Network.stack`) puts a leading batch axis
in front.

The contract (:class:`Law`), implemented by every law:

- ``force(e, rate)`` -- force, N; ``elastic_force(e)`` without the dashpot;
- ``energy(e)`` -- energy stored in the link, J;
- ``stiffness(e)`` -- tangent stiffness dF/d(delta), N/m (the linearised dynamics, the
  Verlet stability limit);
- ``dissipation(e, rate)`` -- power taken out by the dashpot, W, never negative;
- ``extension_at_energy(E)`` -- the extension at which the law stores the energy E (the
  scale of the integrators' absolute tolerances);
- ``stiffness_bound(X)`` -- the largest tangent stiffness up to four times the force carried
  at extension X (the Verlet step);
- ``static_extension(T)`` -- the extension that carries a static tension T (equilibria);
- ``force_into(e, rate, out, work)`` -- the force written into ``out`` (the integrators'
  inner loop: no allocation);
- ``scaled(c)`` -- the law with every force multiplied by c (forces per unit mass);
- ``take(index)``, ``concat(laws)``, ``stack(laws)`` -- the law of some links, of several
  sets of links, of several networks.

The laws here: :class:`PowerLaw` (the lumped contact of paper Eq. (4), unilateral, with
the dashpot of Eq. (7) inside its bracket), :class:`Hertz` (Eq. (1): the power law with
n = 3/2), :class:`LinearSpring` (the bidirectional bending spring of Eq. (2), with the
dashpot gamma_b of Eqs. (5)-(6)) and :class:`Dashpot` (a linear dashpot on its own).  A
dashpot in parallel with a spring is the spring's ``gamma``; ``law + Dashpot(gamma)``
writes the same thing.  The paper's dashpots gamma_c and gamma_b are those of its
contact and bending springs.

Where the energy goes (beyond the paper): :class:`Thornton` (the contact that yields, with
the largest approach of each link as its internal state, ``n_state = 1``),
:class:`HuntCrossley` (a viscoelastic contact whose damping grows with the indentation) and
:func:`loss_factor_spring` (the ring body with a material loss factor).  A law with state
takes the state as ``memory`` (m, one value per link) in ``force``, ``energy`` and
``plastic_work``; without it, the state is the law's own initial value.  The integrators
keep the state per run and update it on accepted steps only
(:mod:`ringchain.numerics.engine.kernels`).
"""

from __future__ import annotations

import functools

import numpy as np
from ringchain.theory import _validate as v

__all__ = [
    "Law",
    "PowerLaw",
    "Hertz",
    "LinearSpring",
    "Dashpot",
    "Thornton",
    "HuntCrossley",
    "loss_factor_spring",
    "power_law_force",
    "linear_spring_force",
]


def power_law_force(delta, delta_rate=0.0, *, K, n, gamma=0.0):
    """Force of an interlocked contact in tension, with its dashpot (paper Eq. (7)).

    Parameters
    ----------
    delta : array_like
        Contact extension u_{i+1} - u_i, m (positive: the rings pull apart).
    delta_rate : array_like, optional
        d(delta)/dt, m/s.
    K : float
        Stiffness, N/m^n (K_c in N/m^1.5 for the Hertz contact, Eq. 1).
    n : float
        Exponent, >= 1 (3/2 for Hertz; the fitted n of Eq. 4 for the power-law chain).
    gamma : float, optional
        Dashpot coefficient, N s/m, >= 0.

    Returns
    -------
    ndarray
        [K delta^n + gamma delta_rate]_+ where delta > 0, else 0; N, positive in tension.

    Notes
    -----
    The paper writes [F(delta) + gamma delta_dot]_+ with F = 0 for delta < 0.  Read
    literally, the dashpot would then act across an open contact (a closing gap with
    delta_dot > 0 would pull); here an open contact (delta <= 0) carries no force at
    all, and an engaged one never pushes (the bracket).  With gamma > 0 the force jumps
    from 0 to gamma delta_dot when a contact closes -- the usual Kelvin-Voigt impact.

    Examples
    --------
    >>> float(power_law_force(2.0, K=3.0, n=1.5))  # 3 * 2^1.5
    8.485281374238571
    >>> float(power_law_force(-1e-6, 5.0, K=3.0, n=1.5, gamma=1.0))  # open contact
    0.0
    """
    delta = v.as_float("delta", delta)
    delta_rate = v.as_float("delta_rate", delta_rate)
    law = PowerLaw(K, n, gamma)
    _broadcastable(delta=delta, delta_rate=delta_rate, **law.params)
    return law.force(delta, delta_rate)


def linear_spring_force(delta, delta_rate=0.0, *, K, gamma=0.0):
    """Force of the bidirectional bending spring of a ring body with its dashpot (Eq. 2).

    Parameters
    ----------
    delta : array_like
        Extension of the ring body along the chain, m (either sign).
    delta_rate : array_like, optional
        d(delta)/dt, m/s.
    K : float
        Bending stiffness K_b, N/m (:func:`ringchain.theory.bending_stiffness`).
    gamma : float, optional
        Dashpot coefficient gamma_b, N s/m, >= 0.

    Returns
    -------
    ndarray
        K delta + gamma delta_rate, N (positive in tension, negative in compression).

    Examples
    --------
    >>> float(linear_spring_force(-2e-6, K=3e6))
    -6.0
    """
    delta = v.as_float("delta", delta)
    delta_rate = v.as_float("delta_rate", delta_rate)
    law = LinearSpring(K, gamma)
    _broadcastable(delta=delta, delta_rate=delta_rate, **law.params)
    return law.force(delta, delta_rate)


def _broadcastable(**arrays) -> None:
    """Raise a ValueError naming the arguments and their shapes if they do not broadcast together."""
    try:
        np.broadcast_shapes(*(np.shape(a) for a in arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{name} {np.shape(a)}" for name, a in arrays.items() if np.ndim(a))
        raise ValueError(f"the arguments' shapes do not broadcast together: {shapes}") from None


def one_or_all(value):
    """A float if every entry of ``value`` is the same (a uniform set of links), else a read-only array."""
    array = np.asarray(value, dtype=float)
    if array.ndim == 0:
        return float(array)
    if array.size and np.ptp(array) == 0:
        return float(array.flat[0])
    array = array.copy()
    array.flags.writeable = False
    return array


class Law:
    """The contract of a contact law (see the module notes); subclasses set :attr:`PARAMETERS`.

    Attributes
    ----------
    one_sided : bool
        Whether the law carries tension only (an interlocked contact) or both signs (a spring).
    energy_kind : {"contact", "bending"}
        Where its stored energy is counted in an :class:`~ringchain.numerics.EnergyBudget`.
    n_state : int
        Internal state variables per link (laws with memory); 0 here.
    """

    #: (name, unit, check) of each parameter, in the constructor's order.
    PARAMETERS: tuple = ()
    one_sided = False
    energy_kind = "bending"
    n_state = 0

    def __init__(self, *values, **named):
        names = [name for name, _, _ in self.PARAMETERS]
        given = dict(zip(names, values, strict=False)) | named
        unknown = set(given) - set(names)
        if unknown or len(values) > len(names):
            raise TypeError(f"{type(self).__name__} takes {', '.join(names)}; got {sorted(unknown) or values}")
        for name, unit, check in self.PARAMETERS:
            value = given.get(name, self._default(name))
            if value is None:
                raise TypeError(f"{type(self).__name__} needs {name} ({unit})")
            setattr(self, name, one_or_all(check(name, value, unit)))

    def _default(self, name):
        return 0.0 if name == "gamma" else None

    # -- the parameters as arrays ----------------------------------------------------------------
    @property
    def params(self) -> dict:
        """{name: value} of the parameters (float, or array with one value per link)."""
        return {name: getattr(self, name) for name, _, _ in self.PARAMETERS}

    def _rebuilt(self, **params) -> Law:
        """The same law with other parameter values, taken as given (already checked)."""
        law = object.__new__(type(self))
        for name, value in (self.params | params).items():
            setattr(law, name, one_or_all(value))
        return law

    @functools.cached_property
    def damped(self) -> bool:
        """Whether the law has a dashpot (its force depends on the rate of extension)."""
        return bool(np.any(np.asarray(getattr(self, "gamma", 0.0)) > 0))

    def take(self, index) -> Law:
        """The law of the links ``index`` (of a set whose parameters are arrays along the last axis)."""
        return self._rebuilt(**{k: p if np.ndim(p) == 0 else p[..., index] for k, p in self.params.items()})

    @classmethod
    def concat(cls, laws, sizes) -> Law:
        """One law over the links of several sets (``sizes[k]`` links of ``laws[k]``), in that order."""
        laws = list(laws)
        params = {}
        for name, _, _ in laws[0].PARAMETERS:
            values = [law.params[name] for law in laws]
            if all(np.ndim(x) == 0 and x == values[0] for x in values):
                params[name] = values[0]
            else:
                params[name] = np.concatenate(
                    [np.broadcast_to(x, (size,)) for x, size in zip(values, sizes, strict=True)]
                )
        return laws[0]._rebuilt(**params)

    @classmethod
    def stack(cls, laws, size: int) -> Law:
        """One law for B networks of one layout, each set of ``size`` links: arrays of shape (B, size)."""
        laws = list(laws)
        params = {}
        for name, _, _ in laws[0].PARAMETERS:
            values = [law.params[name] for law in laws]
            if all(np.ndim(x) == 0 and x == values[0] for x in values):
                params[name] = values[0]  # one number across the stack: the uniform chains' arithmetic
            else:
                params[name] = np.stack([np.broadcast_to(np.asarray(x, dtype=float), (size,)) for x in values])
        return laws[0]._rebuilt(**params)

    def scaled(self, factor) -> Law:
        """The law whose forces are ``factor`` times this one's (forces per unit mass: factor 1/m)."""
        return self._rebuilt(**{name: value * factor for name, value in self.params.items() if name in self.LINEAR})

    #: Parameters that a force is proportional to (what :meth:`scaled` multiplies).
    LINEAR: tuple = ()

    def __add__(self, other):
        if isinstance(other, Dashpot) and "gamma" in self.params and not isinstance(self, Dashpot):
            return self._rebuilt(gamma=self.gamma + other.gamma)
        return NotImplemented

    __radd__ = __add__

    def __repr__(self) -> str:
        shown = ", ".join(f"{k}={v.show(p) if np.ndim(p) else p!r}" for k, p in self.params.items())
        return f"{type(self).__name__}({shown})"

    # -- the contract ----------------------------------------------------------------------------
    def force_into(self, e, rate, out, work) -> None:  # pragma: no cover - abstract
        raise NotImplementedError

    def force(self, e, rate=None) -> np.ndarray:
        """Force of extensions ``e`` (m) and rates ``rate`` (m/s; None: 0), N, positive in tension."""
        e = np.asarray(e, dtype=float)
        shape = np.broadcast_shapes(e.shape, np.shape(rate) if rate is not None else (), self._shape())
        e = np.broadcast_to(e, shape)
        rate = None if rate is None or not self.damped else np.broadcast_to(np.asarray(rate, dtype=float), shape)
        out = np.empty(shape)
        self.force_into(e, rate, out, np.empty(shape))
        return out

    def elastic_force(self, e) -> np.ndarray:
        """Force without the dashpot, N."""
        return self.force(e, None)

    def dissipation(self, e, rate) -> np.ndarray:
        """Power the dashpot takes out, (F - F_elastic) d(delta)/dt, W, per link; never negative.

        Where the bracket of a one-sided law is active, F - F_elastic = gamma rate, so the power
        is gamma rate^2; where it clips the force to zero (the dashpot would push), it is
        -F_elastic rate with rate < 0, again >= 0.
        """
        if not self.damped:
            return np.zeros(np.broadcast_shapes(np.shape(e), self._shape()))
        return (self.force(e, rate) - self.elastic_force(e)) * rate

    def _shape(self) -> tuple:
        shapes = [np.shape(p) for p in self.params.values()]
        return np.broadcast_shapes(*shapes) if shapes else ()


def _exponent(name, value, unit):
    return v.in_range(name, value, 1.0, np.inf, closed_low=True, closed_high=False)


class PowerLaw(Law):
    """The unilateral power-law contact [K delta^n + gamma delta_dot]_+ (paper Eqs. (4) and (7)).

    Parameters
    ----------
    K : float or array_like
        Stiffness, N/m^n.
    n : float or array_like
        Exponent, >= 1.
    gamma : float or array_like, optional
        Dashpot in parallel, inside the bracket, N s/m (see :func:`power_law_force`).

    Examples
    --------
    >>> law = PowerLaw(K=3.0, n=1.5)
    >>> float(law.force(4.0)), float(law.force(-1.0))  # 3 * 4^1.5; an open contact carries nothing
    (24.0, 0.0)
    >>> float(law.energy(4.0)), float(law.stiffness(4.0))  # K delta^(n+1)/(n+1) = 3 * 32/2.5, n K delta^(n-1)
    (38.4, 9.0)
    """

    PARAMETERS = (("K", "N/m^n", v.positive), ("n", "", _exponent), ("gamma", "N s/m", v.nonnegative))
    LINEAR = ("K", "gamma")
    one_sided = True
    energy_kind = "contact"

    def force_into(self, e, rate, out, work):
        np.maximum(e, 0.0, out=out)
        np.power(out, self.n, out=out)
        np.multiply(out, self.K, out=out)
        if rate is not None and self.damped:
            np.multiply(rate, self.gamma, out=work)
            out += work
            np.maximum(out, 0.0, out=out)
            out[e <= 0] = 0.0

    def energy(self, e) -> np.ndarray:
        """K delta_+^(n+1)/(n+1), J."""
        return self.K / (self.n + 1.0) * np.maximum(e, 0.0) ** (self.n + 1.0)

    def stiffness(self, e) -> np.ndarray:
        """n K delta_+^(n-1), N/m (0 where the contact is open)."""
        d = np.maximum(e, 0.0)
        return np.where(d > 0, self.n * self.K * d ** (self.n - 1.0), 0.0)

    def extension_at_energy(self, E) -> np.ndarray:
        """((n + 1) E / K)^(1/(n+1)), m."""
        return ((self.n + 1.0) * E / self.K) ** (1.0 / (self.n + 1.0))

    def stiffness_bound(self, X) -> np.ndarray:
        """n K^(1/n) F^((n-1)/n) at F = 4 K X^n: the tangent stiffness at four times the force at X, N/m."""
        force = 4.0 * self.K * X**self.n
        return self.n * self.K ** (1.0 / self.n) * force ** ((self.n - 1.0) / self.n)

    def static_extension(self, tension) -> np.ndarray:
        """(T/K)^(1/n), m."""
        return (tension / self.K) ** (1.0 / self.n)


def Hertz(K, gamma=0.0) -> PowerLaw:
    """Hertz contact of two tori, K_c delta_+^(3/2) (paper Eq. (1)): the :class:`PowerLaw` with n = 3/2.

    Parameters
    ----------
    K : float or array_like
        K_c, N/m^1.5 (:func:`ringchain.theory.hertz_stiffness`).
    gamma : float or array_like, optional
        Dashpot gamma_c in parallel, inside the bracket, N s/m.

    Examples
    --------
    >>> Hertz(7.5e9).n
    1.5
    """
    return PowerLaw(K, 1.5, gamma)


class LinearSpring(Law):
    """The bidirectional linear spring K delta + gamma delta_dot (the bending spring K_b of paper Eq. (2)).

    Parameters
    ----------
    K : float or array_like
        Stiffness, N/m.
    gamma : float or array_like, optional
        Dashpot in parallel, N s/m (the paper's gamma_b).

    Examples
    --------
    >>> float(LinearSpring(3e6).force(-2e-6))
    -6.0
    """

    PARAMETERS = (("K", "N/m", v.positive), ("gamma", "N s/m", v.nonnegative))
    LINEAR = ("K", "gamma")

    def force_into(self, e, rate, out, work):
        np.multiply(e, self.K, out=out)
        if rate is not None and self.damped:
            np.multiply(rate, self.gamma, out=work)
            out += work

    def energy(self, e) -> np.ndarray:
        """K delta^2/2, J."""
        return 0.5 * self.K * np.square(e)

    def stiffness(self, e) -> np.ndarray:
        return np.broadcast_to(self.K, np.broadcast_shapes(np.shape(e), np.shape(self.K))).astype(float)

    def extension_at_energy(self, E) -> np.ndarray:
        """sqrt(2 E / K), m."""
        return np.sqrt(2.0 * E / self.K)

    def stiffness_bound(self, X) -> np.ndarray:
        return np.broadcast_to(self.K, np.broadcast_shapes(np.shape(X), np.shape(self.K))).astype(float)

    def static_extension(self, tension) -> np.ndarray:
        """T/K, m."""
        return tension / self.K


class Dashpot(Law):
    """A linear dashpot gamma delta_dot, both signs, storing no energy.

    On its own it is a purely viscous link; added to a law (``Hertz(K_c) + Dashpot(g)``) it is
    that law's parallel dashpot ``gamma`` (inside the bracket of a one-sided law).

    Parameters
    ----------
    gamma : float or array_like
        N s/m, >= 0.

    Examples
    --------
    >>> Hertz(7.5e9) + Dashpot(2.0)
    PowerLaw(K=7500000000.0, n=1.5, gamma=2.0)
    """

    PARAMETERS = (("gamma", "N s/m", v.nonnegative),)
    LINEAR = ("gamma",)

    def force_into(self, e, rate, out, work):
        if rate is None:
            out[...] = 0.0
        else:
            np.multiply(rate, self.gamma, out=out)

    def energy(self, e) -> np.ndarray:
        return np.zeros(np.broadcast_shapes(np.shape(e), self._shape()))

    def stiffness(self, e) -> np.ndarray:
        return self.energy(e)

    def extension_at_energy(self, E) -> np.ndarray:
        return np.zeros(np.broadcast_shapes(np.shape(E), self._shape()))

    stiffness_bound = extension_at_energy

    def static_extension(self, tension) -> np.ndarray:
        raise ValueError("a dashpot carries no static tension")


class Thornton(Law):
    r"""Thornton's elastic-perfectly plastic contact with memory of its largest approach (beyond the paper).

    The contact of two tori through its equivalent sphere (:mod:`ringchain.theory.plastic`): the
    Hertz law K delta^(3/2) (paper Eq. (1)) up to the approach at first yield delta_y, then the
    loading line of slope 3/2 K sqrt(delta_y); below the largest approach reached so far,
    delta_m, the elastic Hertz curve of the flattened tip, which opens at the residual approach
    delta_p (:func:`~ringchain.theory.thornton_unloading_force`).  A viscous ``gamma`` may act
    in parallel, inside the bracket, where the contact is engaged (force > 0).

    Parameters
    ----------
    K : float or array_like
        K_c, N/m^1.5 (:func:`ringchain.theory.hertz_stiffness`).
    delta_y : float or array_like
        Approach at first yield, m (:func:`ringchain.theory.first_yield`).
    gamma : float or array_like, optional
        Dashpot in parallel, N s/m.
    delta_max : float or array_like, optional
        Largest approach before the run, m (the initial state; default 0: a virgin contact).

    Notes
    -----
    The internal state of a link is delta_m.  The force at approach delta uses
    max(delta_m, delta), so that a trial state beyond the memory is already on the loading
    line: the force is a function of the state and the memory, and the memory is written by
    the integrator after each accepted step only (:mod:`ringchain.numerics.engine.kernels`).  The
    energy of a link is split into the elastic energy stored on the current curve
    (:meth:`energy`) and the plastic work done so far (:meth:`plastic_work`), both from
    :func:`~ringchain.theory.thornton_energy`.

    Examples
    --------
    >>> law = Thornton(K=1.0, delta_y=1.0)
    >>> float(law.force(2.0)), float(law.force(2.0, memory=3.0))  # loading line; unloading from 3
    (2.5, 1.7077330597891507)
    """

    PARAMETERS = (("K", "N/m^1.5", v.positive), ("delta_y", "m", v.positive), ("gamma", "N s/m", v.nonnegative),
                  ("delta_max", "m", v.nonnegative))  # fmt: skip
    LINEAR = ("K", "gamma")
    one_sided = True
    energy_kind = "contact"
    n_state = 1

    def _default(self, name):
        return 0.0 if name in ("gamma", "delta_max") else None

    def _memory(self, e, memory):
        return np.broadcast_to(self.delta_max if memory is None else np.asarray(memory, dtype=float), np.shape(e))

    def _elastic(self, e, memory):
        from ringchain.theory import thornton_unloading_force

        return thornton_unloading_force(e, delta_max=self._memory(e, memory), K_c=self.K, delta_y=self.delta_y)

    def force_into(self, e, rate, out, work, memory=None):
        out[...] = self._elastic(e, memory)
        if rate is not None and self.damped:
            engaged = out > 0
            np.multiply(rate, self.gamma, out=work)
            out += work
            np.maximum(out, 0.0, out=out)
            out[~engaged] = 0.0

    def force(self, e, rate=None, memory=None) -> np.ndarray:
        """Force, N, at extensions ``e`` (m), rates ``rate`` (m/s) and largest approaches ``memory`` (m)."""
        e = np.asarray(e, dtype=float)
        shape = np.broadcast_shapes(e.shape, np.shape(rate) if rate is not None else (), np.shape(memory),
                                    self._shape())  # fmt: skip
        e = np.broadcast_to(e, shape)
        rate = None if rate is None or not self.damped else np.broadcast_to(np.asarray(rate, dtype=float), shape)
        out = np.empty(shape)
        self.force_into(e, rate, out, np.empty(shape), None if memory is None else np.broadcast_to(memory, shape))
        return out

    def elastic_force(self, e, memory=None) -> np.ndarray:
        return self.force(e, None, memory)

    def dissipation(self, e, rate, memory=None) -> np.ndarray:
        """Power the dashpot takes out, W (the plastic work is :meth:`plastic_work`)."""
        if not self.damped:
            return np.zeros(np.broadcast_shapes(np.shape(e), self._shape()))
        return (self.force(e, rate, memory) - self.elastic_force(e, memory)) * rate

    def _energies(self, e, memory):
        from ringchain.theory import thornton_energy

        e = np.asarray(e, dtype=float)
        shape = np.broadcast_shapes(e.shape, np.shape(memory), self._shape())
        e = np.broadcast_to(e, shape)
        return thornton_energy(e, delta_max=self._memory(e, memory), K_c=self.K, delta_y=self.delta_y)

    def energy(self, e, memory=None) -> np.ndarray:
        """Elastic energy stored on the current curve, J (2/5 F (delta - delta_p) once yielded)."""
        return self._energies(e, memory)[0]

    def plastic_work(self, e, memory=None) -> np.ndarray:
        """Plastic work done on the contact up to max(memory, delta), J (zero below first yield)."""
        return self._energies(e, memory)[1]

    def _hertz(self) -> PowerLaw:
        return PowerLaw(self.K, 1.5)

    def stiffness(self, e, memory=None) -> np.ndarray:
        """dF/d(delta), N/m: the loading slope 3/2 K sqrt(delta_y) on the line, the tip's Hertz slope below it."""
        e = np.asarray(e, dtype=float)
        h = 1e-7 * np.maximum(np.abs(e), self.delta_y)
        return (self.force(e + h, None, memory) - self.force(e - h, None, memory)) / (2 * h)

    def extension_at_energy(self, E) -> np.ndarray:
        """The Hertz curve's ((5/2) E/K)^(2/5), m (a tolerance scale)."""
        return self._hertz().extension_at_energy(E)

    def stiffness_bound(self, X) -> np.ndarray:
        """The Hertz curve's bound (the loading line and the tip's curve are never stiffer), N/m."""
        return self._hertz().stiffness_bound(X)

    def static_extension(self, tension) -> np.ndarray:
        """Extension carrying the static ``tension`` (N) from the law's memory ``delta_max``, m.

        On the loading curve where the tension exceeds the loading force at delta_max (the
        Hertz inverse up to F_y = K delta_y^(3/2), then (2 T/(K sqrt(delta_y)) + delta_y)/3);
        else on the curve of the flattened tip, delta_p + (delta_m - delta_p)(T/F_m)^(2/3).
        """
        from ringchain.theory import thornton_loading_force, thornton_residual_indentation

        T = np.maximum(np.asarray(tension, dtype=float), 0.0)
        K, dy, dm = self.K, self.delta_y, np.maximum(self.delta_max, self.delta_y)
        loading = np.where(T <= K * dy**1.5, (T / K) ** (2.0 / 3.0), (2.0 * T / (K * np.sqrt(dy)) + dy) / 3.0)
        F_m = thornton_loading_force(dm, K_c=K, delta_y=dy)
        delta_p = thornton_residual_indentation(dm, delta_y=dy)
        unloading = delta_p + (dm - delta_p) * (T / F_m) ** (2.0 / 3.0)
        return np.where(T >= F_m, loading, unloading)

    def remembered(self, memory) -> Thornton:
        """The same law whose initial memory is ``memory`` (m per link): a contact flattened by an earlier run."""
        memory = np.asarray(v.nonnegative("memory", memory, "m"), dtype=float)
        return self._rebuilt(delta_max=np.maximum(memory, 0.0))


class HuntCrossley(Law):
    r"""Viscoelastic contact [K delta^n (1 + 3/2 alpha delta_dot)]_+ (Hunt and Crossley 1975; beyond the paper).

    The damping force 3/2 alpha K delta^n delta_dot grows with the indentation as the contact
    area does (the Kuwabara-Kono form, whose damping is proportional to the contact
    stiffness times the rate), so that it vanishes when the contact opens and closes: no jump
    of the force at first touch, unlike a constant dashpot.  The bracket stops it pulling.

    Parameters
    ----------
    K : float or array_like
        Stiffness, N/m^n (K_c of paper Eq. (1) for n = 3/2).
    n : float or array_like, optional
        Exponent, >= 1; default 3/2.
    alpha : float or array_like, optional
        Damping constant, s/m, >= 0.  For small alpha V a collision at speed V rebounds with
        e = 1 - alpha V (Hunt and Crossley's linearisation).

    Examples
    --------
    >>> law = HuntCrossley(K=3.0, alpha=0.2)
    >>> round(float(law.force(4.0, 1.0)), 12)  # 3 * 8 * (1 + 0.3)
    31.2
    """

    PARAMETERS = (("K", "N/m^n", v.positive), ("n", "", _exponent), ("alpha", "s/m", v.nonnegative))
    LINEAR = ("K",)
    one_sided = True
    energy_kind = "contact"

    def _default(self, name):
        return {"n": 1.5, "alpha": 0.0}.get(name)

    @functools.cached_property
    def damped(self) -> bool:
        return bool(np.any(np.asarray(self.alpha) > 0))

    def _elastic(self) -> PowerLaw:
        return PowerLaw(self.K, self.n)

    def force_into(self, e, rate, out, work):
        self._elastic().force_into(e, None, out, work)
        if rate is not None and self.damped:
            np.multiply(rate, 1.5 * self.alpha, out=work)
            work += 1.0
            out *= work
            np.maximum(out, 0.0, out=out)

    def energy(self, e) -> np.ndarray:
        return self._elastic().energy(e)

    def stiffness(self, e) -> np.ndarray:
        return self._elastic().stiffness(e)

    def extension_at_energy(self, E) -> np.ndarray:
        return self._elastic().extension_at_energy(E)

    def stiffness_bound(self, X) -> np.ndarray:
        return self._elastic().stiffness_bound(X)

    def static_extension(self, tension) -> np.ndarray:
        return self._elastic().static_extension(tension)


def loss_factor_spring(K, *, eta, omega) -> LinearSpring:
    """The ring body's bending spring with a material loss factor: K and the dashpot gamma = eta K/omega.

    Parameters
    ----------
    K : float or array_like
        Bending stiffness K_b, N/m (paper Eq. (2)).
    eta : float or array_like
        Loss factor, >= 0 (energy lost per cycle over 2 pi times the largest stored energy; of
        order 1e-4 to 1e-3 for steels).
    omega : float
        Angular frequency at which the loss factor holds, rad/s: the pulse's (pi over its width)
        for a chain's leading pulse.

    Returns
    -------
    LinearSpring
        A Kelvin-Voigt spring: under a harmonic motion at omega it loses 2 pi eta times its largest
        stored energy per cycle, as a hysteretic (frequency-independent) loss factor would; at other
        frequencies its loss grows as omega.  This choice keeps the law in the engine's state (no
        fractional or Prony states) and is exact at the frequency that carries the pulse.

    Examples
    --------
    >>> loss_factor_spring(3.3e6, eta=1e-3, omega=1e5).gamma  # N s/m
    0.033
    """
    K = v.positive("K", K, "N/m")
    eta = v.nonnegative("eta", eta)
    omega = v.positive("omega", omega, "rad/s")
    return LinearSpring(K, np.asarray(eta * K / omega, dtype=float))
