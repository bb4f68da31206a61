r"""Equations of motion of the two lattice models of the paper (Sec. III.B), vectorised.

Both models are a line of point masses ("sites") joined by nearest-neighbour bonds,
written here in one form, :class:`Lattice`:

- **power-law chain** (paper Eq. (7)): one site per ring; every bond is a
  unilateral contact with force :func:`power_law_force`, [K delta^n + gamma delta_dot]_+;
- **dual-spring chain** (paper Eqs. (5)-(6)): two sites of mass m/2 per ring;
  the bonds alternate between the linear, bidirectional bending spring of a ring body
  (:func:`linear_spring_force`, F_b = K_b delta plus its dashpot) and the unilateral
  Hertz contact between rings (:func:`power_law_force` with n = 3/2, K = K_c).

Conventions (tension positive, ARCHITECTURE.md): the axis points away from the impact,
site 0 is at the impact end, bond k joins site k to site k+1 and its extension is
delta_k = x_{k+1} - x_k, where x is a site's displacement from the configuration in
which every bond is just taut and unloaded.  A positive bond force pulls its two sites
together.  With a fixed support, one more bond joins the last site to an anchor that
does not move (displacement 0).

Everything is vectorised over rings and over leading axes (a batch of runs, or
time samples): arrays of site quantities have shape (..., n_sites), arrays of bond
quantities (..., n_bonds).  There is no Python loop over rings.  Several chains of one
layout are one lattice too (:meth:`Lattice.stack`): their parameters stacked along a
leading axis, one run per chain, integrated together.
"""

from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np
from ringchain.theory import _validate as v
from ringchain.theory import linear

__all__ = ["STANDARD_GRAVITY", "power_law_force", "linear_spring_force", "Lattice"]

#: Standard acceleration of gravity, m/s^2 (CGPM 1901, exact by definition; defined in :mod:`ringchain.theory.linear`).
STANDARD_GRAVITY = linear.STANDARD_GRAVITY


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
    K = v.positive("K", K, "N/m^n")
    n = v.in_range("n", n, 1.0, np.inf, closed_low=True, closed_high=False)
    gamma = v.nonnegative("gamma", gamma, "N s/m")
    _broadcastable(delta=delta, delta_rate=delta_rate, K=K, n=n, gamma=gamma)
    engaged = delta > 0
    force = K * np.where(engaged, delta, 0.0) ** n + gamma * delta_rate
    return np.where(engaged, np.maximum(force, 0.0), 0.0)


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
    K = v.positive("K", K, "N/m")
    gamma = v.nonnegative("gamma", gamma, "N s/m")
    _broadcastable(delta=delta, delta_rate=delta_rate, K=K, gamma=gamma)
    return K * delta + gamma * delta_rate


def _broadcastable(**arrays) -> None:
    """Raise a ValueError naming the arguments and their shapes if they do not broadcast together."""
    try:
        np.broadcast_shapes(*(a.shape for a in arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{name} {a.shape}" for name, a in arrays.items() if a.ndim)
        raise ValueError(f"the arguments' shapes do not broadcast together: {shapes}") from None


@dataclass(frozen=True, eq=False)
class Lattice:
    """Sites joined by nearest-neighbour bonds: the common form of both paper models.

    Usually built by :class:`ringchain.numerics.Chain`.  Every bond k has a contact part
    and a spring part, given per bond, so that one vectorised expression serves both
    models: a contact bond has K_spring = gamma_spring = 0, a spring bond has
    K_contact = gamma_contact = 0.  The force of bond k is

        K_spring delta + gamma_spring delta_dot
        + (delta > 0) [K_contact delta^n + gamma_contact delta_dot]_+.

    Parameters
    ----------
    mass : ndarray, shape (n_sites,)
        Inertial mass of each site, kg.
    weight_mass : ndarray, shape (n_sites,)
        Mass of each site that gravity acts on, kg.
    K_contact : ndarray, shape (n_bonds,)
        Contact stiffness of each bond, N/m^n (0 for a spring bond).
    n : float or ndarray, shape (n_bonds,)
        Contact exponent, one for all bonds or one per bond (any value >= 1 on a spring bond).
    K_spring : ndarray, shape (n_bonds,)
        Linear stiffness of each bond, N/m (0 for a contact bond).
    gamma_contact, gamma_spring : ndarray, shape (n_bonds,)
        Dashpots, N s/m.

    Notes
    -----
    n_bonds is n_sites - 1 (free far end) or n_sites (the last bond ties the last site to
    a fixed anchor).  A lattice made by :meth:`stack` holds B chains, every array with a
    leading axis of length B (:attr:`batch_shape`); it drives states of shape
    (B, n_sites), one run per chain.
    """

    mass: np.ndarray
    weight_mass: np.ndarray
    K_contact: np.ndarray
    n: float | np.ndarray
    K_spring: np.ndarray
    gamma_contact: np.ndarray
    gamma_spring: np.ndarray

    def __post_init__(self):
        for name in ("mass", "weight_mass", "K_contact", "K_spring", "gamma_contact", "gamma_spring"):
            object.__setattr__(self, name, np.asarray(getattr(self, name), dtype=float))
        try:
            np.broadcast_shapes(np.shape(self.n), self.K_contact.shape)
        except ValueError:
            raise ValueError(
                f"n must be one number or one per bond ({self.n_bonds}), got shape {np.shape(self.n)}"
            ) from None
        if self.n_bonds not in (self.n_sites - 1, self.n_sites):
            raise ValueError(
                f"{self.n_sites} sites need {self.n_sites - 1} or {self.n_sites} bonds, got {self.n_bonds}"
            )

    @classmethod
    def stack(cls, lattices) -> Lattice:
        """Lattices of several chains of one layout stacked along a leading axis: one run each.

        Parameters
        ----------
        lattices : sequence of Lattice, length B
            Lattices with the same numbers of sites and bonds (e.g. the
            :attr:`~ringchain.numerics.Chain.lattice` of chains of one model, number of rings
            and support, whatever their parameters, uniform or varying along the chain).

        Returns
        -------
        Lattice
            Arrays of shape (B, n_sites) and (B, n_bonds); ``n`` one number if every lattice
            has the same single exponent, else shape (B, n_bonds).  Its :meth:`stepper` and
            :meth:`first_order_rhs` take a batch of B states, row b being a run of lattice b:
            the same code as a batch of runs of one chain (the fast path of the two chain
            models included), each coefficient an array across the stack where it differs.

        Examples
        --------
        >>> a = Lattice([1.0, 1.0], [1.0, 1.0], [2.0], 1.5, [0.0], [0.0], [0.0])
        >>> b = Lattice([1.0, 2.0], [1.0, 2.0], [3.0], 1.5, [0.0], [0.0], [0.0])
        >>> both = Lattice.stack([a, b])
        >>> both.batch_shape, both.n_sites, both.n_bonds
        ((2,), 2, 1)
        >>> both.accelerations([[0.0, 1.0], [0.0, 1.0]], None, g=0.0).tolist()  # K delta^n / m
        [[2.0, -2.0], [3.0, -1.5]]
        """
        lattices = list(lattices)
        if not lattices:
            raise ValueError("stack needs at least one lattice")
        for i, lat in enumerate(lattices):
            if not isinstance(lat, Lattice):
                raise TypeError(f"lattices[{i}] must be a Lattice, got {type(lat).__name__}")
            if lat.batch_shape:
                raise ValueError(f"lattices[{i}] is already a stack of {lat.batch_shape[0]} lattices")
            if (lat.n_sites, lat.n_bonds) != (lattices[0].n_sites, lattices[0].n_bonds):
                raise ValueError(
                    f"lattices of one layout are stacked: lattices[{i}] has {lat.n_sites} sites and {lat.n_bonds} "
                    f"bonds, lattices[0] {lattices[0].n_sites} and {lattices[0].n_bonds}"
                )
        names = ("mass", "weight_mass", "K_contact", "K_spring", "gamma_contact", "gamma_spring")
        arrays = {name: np.stack([getattr(lat, name) for lat in lattices]) for name in names}
        exponents = [lat.n for lat in lattices]
        if all(np.ndim(n) == 0 and n == exponents[0] for n in exponents):
            n = exponents[0]  # one number: the power of the uniform chains, a scalar exponent
        else:
            n = np.stack([np.broadcast_to(np.asarray(n, dtype=float), lattices[0].K_contact.shape) for n in exponents])
        return cls(n=n, **arrays)

    @property
    def batch_shape(self) -> tuple:
        """() for one chain; (B,) for a :meth:`stack` of B chains."""
        return self.mass.shape[:-1]

    @property
    def n_sites(self) -> int:
        return self.mass.shape[-1]

    @property
    def n_bonds(self) -> int:
        return self.K_contact.shape[-1]

    @property
    def anchored(self) -> bool:
        """Whether the last bond ties the last site to a fixed support."""
        return self.n_bonds == self.n_sites

    @functools.cached_property
    def damped(self) -> bool:
        """Whether any dashpot is present (the motion then depends on velocities)."""
        return bool(np.any(self.gamma_contact > 0) or np.any(self.gamma_spring > 0))

    @functools.cached_property
    def _has_springs(self) -> bool:
        return bool(np.any(self.K_spring > 0))

    # -- kinematics ------------------------------------------------------------------
    def extension(self, x, out=None):
        """Bond extensions delta_k = x_{k+1} - x_k (the anchor at 0), shape (..., n_bonds)."""
        x = np.asarray(x, dtype=float)
        if out is None:
            out = np.empty((*x.shape[:-1], self.n_bonds))
        np.subtract(x[..., 1:], x[..., :-1], out=out[..., : self.n_sites - 1])
        if self.anchored:
            # Not np.negative: NumPy 2.4.6 returns wrong values for np.negative with a strided
            # input and a non-contiguous out (e.g. the last column of a batch); subtract is right.
            np.subtract(0.0, x[..., -1], out=out[..., -1])
        return out

    # -- forces ----------------------------------------------------------------------
    def bond_forces(self, e, e_rate=None, bonds=None):
        """Bond forces, N, positive in tension, from extensions (and their rates if damped).

        ``bonds`` (an index array) says which bonds the last axis of ``e`` holds; default
        every bond.
        """
        f = np.empty_like(e)
        self._bond_forces_into(e, e_rate, f, np.empty_like(e), bonds=bonds)
        return f

    def elastic_forces(self, e):
        """Bond forces without the dashpots, N."""
        f = np.empty_like(e)
        self._bond_forces_into(e, None, f, np.empty_like(e), elastic_only=True)
        return f

    def _bond_forces_into(self, e, e_rate, f, work, elastic_only=False, bonds=None):
        K_contact, K_spring, gamma_contact, gamma_spring = (
            (self.K_contact, self.K_spring, self.gamma_contact, self.gamma_spring) if bonds is None else
            (self.K_contact[..., bonds], self.K_spring[..., bonds], self.gamma_contact[..., bonds],
             self.gamma_spring[..., bonds])
        )  # fmt: skip
        n = self.n if bonds is None or np.ndim(self.n) == 0 else self.n[..., bonds]
        np.maximum(e, 0.0, out=work)
        np.power(work, n, out=work)
        work *= K_contact
        if self.damped and not elastic_only:
            work += gamma_contact * e_rate
            np.maximum(work, 0.0, out=work)
            work[e <= 0] = 0.0
        if self._has_springs:
            np.multiply(e, K_spring, out=f)
            if self.damped and not elastic_only:
                f += gamma_spring * e_rate
            f += work
        else:
            f[...] = work

    def accelerations(self, x, u, g=STANDARD_GRAVITY):
        """Site accelerations, m/s^2, shape (..., n_sites), of displacements x and velocities u.

        Parameters
        ----------
        x, u : ndarray, shape (..., n_sites)
            Site displacements (m) and velocities (m/s) along the axis pointing away from
            the impact (up, for the hanging chain).
        g : float
            Gravity, m/s^2, acting along -axis on the weight masses (0 for no gravity).
        """
        x = np.asarray(x, dtype=float)
        out = np.empty_like(x)
        self.stepper(x.shape[:-1], g)(x, u, out)
        return out

    @functools.cached_property
    def _chain_pattern(self):
        """(contacts, springs) if the bonds are all contacts, or alternate spring, contact, ... (the
        two chain models), as slices of the bonds; else None (see :meth:`stepper`).  A stack has the
        pattern if every chain of it has."""
        contact, spring = self.K_contact > 0, self.K_spring > 0
        if not spring.any() and contact.all():
            return slice(None), None
        odd, even = (Ellipsis, slice(1, None, 2)), (Ellipsis, slice(0, None, 2))
        if contact[odd].all() and spring[even].all() and not contact[even].any() and not spring[odd].any():
            return slice(1, None, 2), slice(0, None, 2)
        return None

    @staticmethod
    def _one_or_all(array):
        """A float if every entry of ``array`` is the same, else the array."""
        return float(array.flat[0]) if array.size and np.ptp(array) == 0 else array

    def stepper(self, batch_shape, g):
        """A function ``(x, u, out)`` writing the accelerations into ``out``.

        The inner loop of the integrators: work arrays and their views are made once,
        so a call is about ten NumPy operations on whole arrays.  For an undamped chain of
        the two models' layout (the usual case) the forces are computed on the contact and
        spring bonds separately, each coefficient a number when it is the same along the
        chain and an array when it varies, and per unit mass when the masses are equal (the
        uniform chain: one code for both, the uniform chain's arithmetic unchanged);
        otherwise by the general expression of the class docstring, and the call returns
        ``(e, e_rate, f)`` (extensions, their rates and the bond forces) for the
        dissipation rate.  ``u`` is only read if the lattice is
        damped.  One stepper must not be called from two threads at once.
        """
        S, nb, n = self.n_sites, self.n_bonds, self.n
        e = np.empty((*batch_shape, nb))
        e_head = e[..., : S - 1]
        e_tail = e[..., S - 1] if self.anchored else None
        # Padded forces: [0, bond 0, ..., bond nb-1, (0 if the far end is free)].  Site k
        # is pulled up by bond k and down by bond k-1; site 0 has no bond below it.
        padded = np.zeros((*batch_shape, S + 1))
        f = padded[..., 1 : 1 + nb]
        above, below = padded[..., 1:], padded[..., :-1]
        pattern = None if self.damped else self._chain_pattern

        # Site slices: plain ones for a single run (cheaper than ``...`` indexing).
        upper, lower, last = (slice(1, None), slice(None, -1), S - 1) if not batch_shape else (
            (Ellipsis, slice(1, None)), (Ellipsis, slice(None, -1)), (Ellipsis, S - 1))  # fmt: skip

        def extension_into(x):
            np.subtract(x[upper], x[lower], out=e_head)
            if e_tail is not None:
                np.subtract(0.0, x[last], out=e_tail)  # see extension(): not np.negative

        if pattern is not None:
            # Undamped chain: contact and spring bonds computed separately.  Each coefficient is
            # a number when it is the same along the chain (the uniform chain: its speed and
            # its rounding), else an array; with equal masses the forces are per unit mass.
            contacts, springs = pattern
            one = self._one_or_all
            K, m, m_g = one(self.K_contact[..., contacts]), one(self.mass), one(self.weight_mass)
            K_s = one(self.K_spring[..., springs]) if springs is not None else 0.0
            n_c = n if np.ndim(n) == 0 else one(n[..., contacts])
            if np.ndim(m) == 0:
                K_per_mass, K_s_per_mass, g_acc, inv_mass = K / m, K_s / m, g * m_g / m, None
            else:
                K_per_mass, K_s_per_mass, g_acc, inv_mass = K, K_s, one(g * self.weight_mass / self.mass), 1.0 / m
            e_c, f_c = e[..., contacts], f[..., contacts]
            e_s, f_s = (e[..., springs], f[..., springs]) if springs is not None else (None, None)
            subtract, maximum, power, multiply = np.subtract, np.maximum, np.power, np.multiply

            def accelerations_into(x, u, out):
                subtract(x[upper], x[lower], out=e_head)
                if e_tail is not None:
                    subtract(0.0, x[last], out=e_tail)  # see extension(): not np.negative
                maximum(e_c, 0.0, out=f_c)
                power(f_c, n_c, out=f_c)
                multiply(f_c, K_per_mass, out=f_c)
                if e_s is not None:
                    multiply(e_s, K_s_per_mass, out=f_s)
                subtract(above, below, out=out)
                if inv_mass is not None:
                    multiply(out, inv_mass, out=out)
                subtract(out, g_acc, out=out)

            return accelerations_into

        e_rate = np.empty((*batch_shape, nb)) if self.damped else None
        work = np.empty((*batch_shape, nb))
        inv_mass = 1.0 / self.mass
        gravity_acc = g * self.weight_mass * inv_mass

        def accelerations_into(x, u, out):
            extension_into(x)
            if e_rate is not None:
                self.extension(u, out=e_rate)
            self._bond_forces_into(e, e_rate, f, work)
            np.subtract(above, below, out=out)
            np.multiply(out, inv_mass, out=out)
            np.subtract(out, gravity_acc, out=out)
            return e, e_rate, f

        return accelerations_into

    # -- energy ----------------------------------------------------------------------
    def kinetic_energy(self, u):
        """Sum of m u^2/2 over sites, J, shape (...)."""
        return 0.5 * np.sum(self.mass * np.square(u), axis=-1)

    def contact_energy(self, e):
        """Elastic energy of the contacts, sum of K delta_+^(n+1)/(n+1), J."""
        d = np.maximum(e, 0.0)
        if np.ndim(self.n):  # one exponent per bond
            return np.sum(self.K_contact / (self.n + 1.0) * d ** (self.n + 1.0), axis=-1)
        return np.sum(self.K_contact * d ** (self.n + 1.0), axis=-1) / (self.n + 1.0)

    def spring_energy(self, e):
        """Elastic energy of the linear springs, sum of K_s delta^2/2, J."""
        return 0.5 * np.sum(self.K_spring * np.square(e), axis=-1)

    def gravity_energy(self, x, g=STANDARD_GRAVITY):
        """Potential energy of the weights, sum of m_gravity g x, J (zero at x = 0)."""
        return g * np.sum(self.weight_mass * x, axis=-1)

    def dissipation_rate(self, e, e_rate, f=None):
        """Power taken out by the dashpots, sum of (F - F_elastic) delta_dot, W; always >= 0.

        Where the bracket of a contact is active, F - F_elastic = gamma delta_dot, so the
        power is gamma delta_dot^2; where it clips the force to zero (the dashpot would
        push), F - F_elastic = -K delta^n with delta_dot < 0, so the power is again >= 0.
        """
        if f is None:
            f = self.bond_forces(e, e_rate)
        return np.sum((f - self.elastic_forces(e)) * e_rate, axis=-1)

    # -- first-order system for scipy --------------------------------------------------
    #: Lower and upper bandwidth of the Jacobian of :meth:`first_order_rhs` (site-interleaved
    #: state): the velocity of site k depends on x and u of sites k-1, k, k+1.
    BANDWIDTH = (3, 2)

    def first_order_rhs(self, n_runs: int, g: float):
        """Right-hand side f(t, y) of a batch of ``n_runs`` runs as one flat state.

        The state is [x, u] interleaved per site, shape (n_runs, n_sites, 2), flattened,
        then the energy W dissipated so far by each run (only if the lattice is damped).
        Interleaving keeps the Jacobian banded (:attr:`BANDWIDTH`), which implicit and
        stiff-switching solvers exploit; the W entries lie outside the band, which only
        makes the Newton matrix approximate (W feeds back into nothing).  A :meth:`stack`
        of B chains takes ``n_runs = B``, run b on chain b.
        """
        if self.batch_shape and (n_runs,) != self.batch_shape:
            raise ValueError(
                f"a stack of {self.batch_shape[0]} lattices integrates one run each, got n_runs = {n_runs}"
            )
        S = self.n_sites
        n_xu = 2 * n_runs * S
        shape = () if n_runs == 1 and not self.batch_shape else (n_runs,)  # one run: plain 1-d views
        accelerations_into = self.stepper(shape, g)
        damped = self.damped
        x_part, u_part = slice(0, n_xu, 2), slice(1, n_xu, 2)

        def rhs(t, y):
            dy = np.empty_like(y)
            u = y[u_part]
            dy[x_part] = u
            x, a = y[x_part], dy[u_part]
            if shape:
                x, u, a = x.reshape(n_runs, S), u.reshape(n_runs, S), a.reshape(n_runs, S)
            forces = accelerations_into(x, u, a)
            if damped:
                dy[n_xu:] = self.dissipation_rate(*forces)
            return dy

        return rhs
