r"""The static state of a network of rigid rings under gravity, its fixed rings held: :meth:`Rings.equilibrium`.

:func:`equilibrium` finds where the loads on every free ring vanish -- gravity, m g along -z, and the forces and
torques of every contact (the network's own contact law, every local minimum of the distance of two centre
circles a contact) -- over the centres and orientations of the free rings.  Each ring moves from its pose of
the current iteration by a translation and a rotation vector theta (q = exp(theta) q_0); the loads are minus
the gradient of the potential energy over these, the torques mapped through the left Jacobian of SO(3)
(the identity at theta = 0, where every iteration starts).  The variables are scaled so that the solver sees
numbers of order one: translations in tube radii r, rotations in units that move a rim by r, loads in units of
the heaviest weight m g (torques of m g R).

Why not a first-order method alone.  A draped sheet couples stiff contacts to floppy modes: the Hertz contact under a
ring's weight, k = 3/2 K^(2/3) (m g)^(1/3), is some 1e4-1e5 m g per tube radius, the swing of the sheet as a
pendulum about r/L m g per tube radius (L the sheet's length).  Gradient methods (damped dynamics, L-BFGS) then
take of order sqrt(1e7) steps per decade of the residual; and contacts softened too far (1e-6 of their stiffness)
let rings pass through one another (a soft tube gives way under a few weights and the pair unlinks).

Why not Newton's method alone.  Each Newton iteration costs some 100 evaluations of the loads (the colours of the
stiffness matrix), and its model of the loads holds only over a step of a few approaches of a contact; a sheet
that falls and folds into its drape from the pose it was built in moves far, and Newton's method spends hundreds
of iterations on the way (a 10 x 10 sheet: 50 iterations in each of the four stages, residual still 3e3 m g).

So each stage (below) runs two phases.  The first, a descent, brings the pose to the stage's tolerance at one
evaluation per step when it can: L-BFGS (Liu and Nocedal, Math. Program. 45, 503 (1989); the two-loop recursion of
Nocedal and Wright, Numerical Optimization, 2nd ed. (2006), Algorithm 7.4) on the energy, the scaled loads its
gradient, the spin about each ring's axis projected out of both, steps capped at ``STEP``, ``MEMORY`` pairs.  Its
initial inverse Hessian is the stiffness matrix of Newton's method below (its symmetric part, shifted by the
smallest multiple of its largest diagonal, 1e-8, 1e-6, ..., that makes it positive definite), rebuilt every
``REFRESH`` accepted steps (``PRECONDITION``; else s.y / y.y): the matrix carries the stiff contacts, which a plain
L-BFGS resolves only over thousands of steps, and the pairs carry the change of the matrix between builds (a 4 x 4
sheet to 1e-6 m g: 18,000 steps and 37 s of CPU without it, 1,000 steps and 3 s with it).  A step is halved until
the energy falls by Armijo's fraction 1e-4 of its slope or the residual falls (``SEARCH`` halvings, then the plain
gradient); where neither falls along the gradient (rounding, or the scan finding or missing a minimum next to a
fold), it follows the loads by overdamped steps of the smallest inverse curvature met, at most ``FORCED`` in a row.
Every trial pose searches its contacts from scratch: the warm-started search costs little less (30 x 30 sheet: 26 ms
against 31 ms an evaluation) and cannot see a minimum born away from the ones it follows (searched from scratch only
every 25 steps, a ring of a 10 x 10 sheet was found 426 m g deep in a neighbour's tube).  It stops at ``HANDOVER``
m g (or the stage's tolerance if larger) or after ``DESCENT`` steps, and Newton's method (below) polishes what is
left; its pose is kept only where its residual is lower than the descent's.  A 30 x 30 sheet's softest stage once
stopped at 10.4 m g on a pose where the cold search missed a twin minimum lying with its maximum between two of the
scan's samples, which the steps tried out of it found, 6.1e-5 J higher; with the search's look between samples
(:mod:`~ringchain.numerics.engine.rings_kernels`) the descent moves on from that pose, to 3.9e-3 m g in 500 steps.
The whole drape, run once with an earlier version of that look, stopped again at 12.5 m g, on a pose where that
version missed 10 minima and the present one none.  With the differences and factorisations checked (below) it is
solved from the start: 7.8e-7 m g after 1,647 s of CPU, 464 MB resident (benchmarks/bench_rings_drape.py).
Measured against it: FIRE (Bitzek, Koskinen, Gaehler, Moseler and Gumbsch, Phys. Rev. Lett. 97, 170201 (2006),
with the parameters of FIRE 2.0, Guenole et al., Comput. Mater. Sci. 175, 109584 (2020)), on the same scaled
variables with the time step bounded by the stiffest curvature, stalled at 0.4-0.8 m g on a 4 x 4 sheet after
3,000 steps (its global restart, where the power of the loads turns negative, fires every 10-20 steps on the
contacts' fast modes and stops the slow swing), where L-BFGS (unpreconditioned) reached 1e-2 m g in 1,600.

The solver: pseudo-transient continuation (Newton's method on the loads with a pseudo-time step tau,
(H + I / tau) dx = -g, tau grown as the residual falls: Kelley and Keyes, SIAM J. Numer. Anal. 35, 508 (1998)).
The stiffness matrix H (minus the Jacobian of the scaled loads, symmetrised) is built by finite differences of
the compiled loads, :meth:`~ringchain.numerics.layouts.rings.RingsDynamics.contact_loads`, warm-started from call
to call: rings whose bounding spheres (radius R + r) overlap no common neighbour's are moved together (a
distance-2 colouring of the graph of rings that can touch), so a matrix costs 6 times the number of colours
evaluations, whatever the number of rings.  The spin of a torus about its own axis moves no point of it, a
null direction of the loads, pinned in H.  (H + I / tau) is factorised without pivoting off the diagonal
(SuperLU), whose pivots give its inertia: tau shrinks until it is positive definite, so the step goes downhill.
Steps are capped at ``STEP`` tube radii in every variable (no ring jumps through another's tube), and accepted
where the energy does not rise beyond its rounding or the residual falls; tau grows by the ratio of the
residuals after an accepted step and shrinks fourfold after a rejected one.  The base and trial poses search
every contact from scratch (the warm start cannot see a minimum born away from those it follows, and a step
moves rings far); the finite differences follow them.

Cliffs and spoilt factors.  Hertz's stiffness of the curvatures grows as A^(-1/2) where a contact's smaller sum of
relative curvatures A falls to zero.  Until the rings' law was bounded near a fold
(:func:`~ringchain.numerics.engine.rings_law.contact_stiffness`: an effective curvature set by the gap's quartic term
there), the compiled law capped its ellipse only at ln(B/A) = 690 and raised an A <= 0 to B e^-690: K_c some
1e150 times its size, a cliff of the energy.  The checks below were made for that law and are kept: a contact
born or lost within a step can still change the energy faster than a difference resolves.  On the 30 x 30
sheet's softest stage, with that law, the descent's trial poses met the cliff
(energies of 1e132-1e144 J, loads up to 1e149 m g; the line search rejects them) and so did the finite differences
of the stiffness matrix: at a base pose where the energy was smooth to 1e-5 r (its change over 1e-7 r matching the
trapezoid rule on the loads to 1.4e-4), the cliff lay 1e-4 r away (2.5e142 J), and a difference across one put
4.6e148 in the matrix, which the pin of the spins (above) copied into every ring's block: the preconditioner's
shifts began at 1e140, and Newton's steps shrank to nothing, each accepted at the cost of a new matrix.  So a
difference whose change of the energy misses the trapezoid rule by more than ``SMOOTH`` of its size is taken
backward, and left out where both miss (:meth:`_Problem.difference`).  And every factorisation (:func:`_factor`) is
refused where its matrix has an entry not finite or its solve of a probe fails (not finite, or a backward error
above ``BACKWARD``), the callers shifting as for a matrix not positive definite: SuperLU checks neither, and the
whole drape before these checks printed BLAS's complaints of an illegal leading dimension from inside it (DTRSV,
DGEMV) and went on.

Stages.  The contacts are first softened (:data:`SOFTENING`: every stiffness, K of the power law or E* of
Hertz's, scaled down), which widens the region where Newton's model holds -- a step along a floppy mode of
length s changes a contact's approach by about s^2 / (2 R), which must stay below the approach
delta ~ (m g / K)^(2/3) -- and each stage starts from the last.  The softest stage keeps the approach under the
weight of 30 rings below a tenth of a tube radius (the paper's steel ring), so no pair unlinks.

The loads are the gradient of the energy: the Hertz law's include the derivative of K_c over the pose
(:func:`~ringchain.numerics.engine.rings_law.stiffness_slopes`), and a contact's share next to a fold
(:func:`~ringchain.numerics.engine.rings_kernels.fold_weights`) enters with its own derivative (the loads of
:func:`~ringchain.numerics.engine.rings_step.loads`).  Without them (measured before they were added) the loads
missed the energy's central differences by 6-30 per cent at twin contacts whose maximum is in overlap, no step
along them lowered the energy there, and the descent of the softest stage of a 30 x 30 sheet stopped at 26-76 m g
with rings deep in one another's tubes, from which the stiffer stages could not recover.  Near the solution
(tau >= ``NEWTON``) Newton's step solves the unsymmetrised matrix (symmetric but for its finite differences),
accepted where the residual falls.  Newton's method alone stalls on a sheet at full stiffness (4 x 4: 2.6e-4 m g
after 200 iterations): a contact barely closed (Hertz's stiffness grows as delta^(1/2) from zero) makes its model
fail for steps longer than its approach, which the line search of the descent takes in its stride.
Converged when the largest residual force on a free ring is below ``force_tol`` m g and the largest torque
below ``force_tol`` m g R (R the largest major radius), checked at the end by a search of every contact from
scratch.
"""

from __future__ import annotations

import numpy as np
from ringchain.theory import STANDARD_GRAVITY
from ringchain.theory import _validate as v

from .rings_layouts import quaternion_about, quaternion_product, rotate

__all__ = ["equilibrium", "static_state", "STEP"]

#: Largest move of an iteration, in tube radii (of a centre, or of a rim by a rotation): no ring jumps through
#: another's tube within one step.
STEP = 0.25

#: Pseudo-time step (in the scaled variables) from which the step solves the unsymmetrised matrix.
NEWTON = 1e2

#: Contact stiffnesses of the stages, as fractions of the law's (module notes).
SOFTENING = (1e-3, 1e-2, 1e-1, 1.0)

#: Finite-difference step of the stiffness matrix, in the scaled variables (tube radii): small beside the
#: approach of a contact under one weight (about 1e-3 r for the paper's steel ring), large beside the rounding
#: of the loads (about 1e-10 m g over stiffnesses of 1e4 m g / r).
DIFFERENCE = 1e-7

#: Largest mismatch of the energy's change over a finite difference of the stiffness matrix and the trapezoid rule on
#: its gradients, as a fraction of their size, below which the difference is taken as a derivative
#: (:meth:`_Problem.difference`): a smooth energy meets it to 1e-4 or better at ``DIFFERENCE`` (measured next to a
#: contact whose stiffness grows a hundredfold within 1e-4 r: 1.4e-4), a cliff of Hertz's stiffness misses by about 1.
#: A lone contact closing within the step (Hertz's force growing from zero) misses by 0.11, and its backward difference
#: is taken, a one-sided derivative as good as the other.
SMOOTH = 0.1

#: Accepted steps of the first phase of each stage (module notes), preconditioned L-BFGS.
DESCENT = 20000

#: Largest residual (in weights m g) at which the first phase hands the pose to Newton's method: none above the
#: stage's tolerance (the preconditioned descent reaches it where Newton's method stalls; module notes).
HANDOVER = 0.0

#: Pairs (step, change of the gradient) that the first phase keeps.
MEMORY = 10

#: Halvings of a step of the first phase before it gives up the direction.
SEARCH = 12

#: Steps in a row that the first phase takes along the loads where neither the energy nor the residual falls.
FORCED = 200

#: Whether the first phase takes the stiffness matrix (its symmetric part, shifted to be positive definite) as its
#: initial inverse Hessian, rebuilt every ``REFRESH`` accepted steps.
PRECONDITION = True

#: Accepted steps of the first phase between two builds of its preconditioner.
REFRESH = 100


def _exp(theta):
    """Unit quaternions of rotation vectors theta (n, 3), rad."""
    t = np.linalg.norm(theta, axis=1)
    axis = np.where(t[:, None] > 0, theta, np.array([[0.0, 0.0, 1.0]]))
    return quaternion_about(axis, t)


def _colours(neighbours):
    """A distance-2 colouring of a graph given as sets of neighbours: no two rings of one colour are neighbours
    or share one (greedy, in order).  Returns a list of index arrays."""
    colour = np.full(len(neighbours), -1)
    for i, near in enumerate(neighbours):
        taken = {colour[j] for j in near}
        taken.update(colour[k] for j in near for k in neighbours[j])
        c = 0
        while c in taken:
            c += 1
        colour[i] = c
    return [np.flatnonzero(colour == c) for c in range(colour.max() + 1)] if len(colour) else []


class _Problem:
    """The scaled loads of the free rings about a base pose, evaluated on one warm-started contact search."""

    def __init__(self, network, g, softening=1.0, start=None):
        self.network, self.g = network, g
        self.dynamics = network.dynamics(softening)
        self.moving = np.flatnonzero(~network.fixed)
        self.masses = network.masses
        self.weight = float(np.max(self.masses)) * g
        self.length = float(max(ring.r for ring in network.rings))
        self.reach = float(max(ring.R for ring in network.rings))
        self.bounds = np.array([ring.R + ring.r for ring in network.rings])
        self.centres, self.orientations = (network.centres.copy(), network.orientations.copy()) if start is None \
            else start  # fmt: skip
        self.evaluations = 0  # of the loads, counted for the record of the phases
        # Energies closer than this differ by rounding (1e-13 of a weight lifted by a tube radius, per free ring), J.
        self.rounding = 1e-13 * max(self.moving.size, 1) * self.weight * self.length
        self.dropped = 0  # columns of the stiffness matrices left out (both differences across a cliff: stiffness)

    def axes(self):
        """The axes (free rings, 3) of the free rings in space at the base pose."""
        return rotate(self.orientations[self.moving], [0.0, 0.0, 1.0])

    def project(self, x):
        """x (6 per free ring) without the spin of each ring about its own axis at the base pose (a null direction of
        the loads: a torus turned about its axis moves no point off itself)."""
        x = x.reshape(-1, 6).copy()
        axes = self.axes()
        x[:, 3:] -= np.sum(x[:, 3:] * axes, axis=1, keepdims=True) * axes
        return x.ravel()

    def pose(self, x):
        x = x.reshape(-1, 6)
        c, q = self.centres.copy(), self.orientations.copy()
        c[self.moving] += x[:, :3] * self.length
        q[self.moving] = quaternion_product(_exp(x[:, 3:] * (self.length / self.reach)), q[self.moving])
        return c, q

    def evaluate(self, x, cold=True):
        """(energy from the base pose, J; scaled gradient (6 per free ring)) at the move x from the base pose, every
        contact searched from scratch (``cold``; the warm start cannot see a minimum of the distance born away from
        the ones it follows, and a step of the solver moves rings far) or followed from the last call."""
        if cold:
            self.dynamics.packed().rest_vectors[:, 0] = 0.0
        self.evaluations += 1
        c, q = self.pose(x)
        elastic, loads = self.dynamics.contact_loads(c, q)
        free = self.moving
        forces = loads[free, :3].copy()
        forces[:, 2] -= self.g * self.masses[free]
        gravity = self.g * float(np.sum(self.masses[free] * (c[free, 2] - self.centres[free, 2])))
        # At theta = 0 the left Jacobian is the identity; away from it the difference is second order in the
        # step, which the finite differences and the acceptance test absorb (every iteration starts at theta = 0).
        grad = np.concatenate([-forces / self.weight, -loads[free, 3:] / (self.weight * self.reach)], axis=1)
        return elastic + gravity, grad.ravel()

    def move(self, x):
        """Make the pose at x the new base."""
        self.centres, self.orientations = self.pose(x)
        self.orientations /= np.linalg.norm(self.orientations, axis=1, keepdims=True)

    def difference(self, x, energy, grad):
        """The change of the gradient over the small move x from the base pose (energy there ``energy``, J, and
        gradient ``grad``, on the followed contacts), divided by ``DIFFERENCE``: forward, or backward where the
        forward move crosses a cliff of the energy; None where both do.

        A cliff: the energy's change differs from the trapezoid rule on the two gradients, (g_0 + g_1).x / 2, by more
        than ``SMOOTH`` of its size (and the rounding), which a smooth energy meets to O(|x|^3).  Hertz's stiffness of
        the curvatures jumps there to some 1e150 times its size (module notes), and a difference across it is no
        derivative."""
        scale = self.weight * self.length  # J per unit of gradient times move
        for sign in (1.0, -1.0):
            moved_energy, moved = self.evaluate(sign * x, cold=False)
            change = moved_energy - energy
            trapezoid = 0.5 * scale * float((grad + moved) @ (sign * x))
            if abs(change - trapezoid) <= SMOOTH * (abs(change) + abs(trapezoid)) + self.rounding:
                return sign * (moved - grad) / DIFFERENCE
        return None

    def stiffness(self, grad):
        """The sparse stiffness matrix d(grad)/dx at the base pose (grad its gradient there), by differences of the
        gradient on the followed contacts (:meth:`difference`)."""
        from scipy import sparse

        free = self.moving
        index = np.full(len(self.masses), -1)
        index[free] = np.arange(free.size)
        pairs = self.network.pairs
        reach = self.bounds[pairs[:, 0]] + self.bounds[pairs[:, 1]]
        close = np.linalg.norm(self.centres[pairs[:, 0]] - self.centres[pairs[:, 1]], axis=1) < reach
        neighbours = [set() for _ in free]
        for i, j in pairs[close]:
            if index[i] >= 0 and index[j] >= 0:
                neighbours[index[i]].add(index[j])
                neighbours[index[j]].add(index[i])
        rows, cols, values = [], [], []
        offsets = np.arange(6)
        energy, _ = self.evaluate(np.zeros(6 * free.size), cold=False)  # the base's energy on the followed contacts
        for group in _colours(neighbours):
            for d in range(6):
                x = np.zeros((free.size, 6))
                x[group, d] = DIFFERENCE
                column = self.difference(x.ravel(), energy, grad)
                if column is None:  # a cliff either side (both within DIFFERENCE of the base): left out
                    self.dropped += 1
                    continue
                for i in group:
                    near = np.fromiter((i, *neighbours[i]), dtype=np.int64)
                    r = (6 * near[:, None] + offsets).ravel()
                    rows.append(r)
                    cols.append(np.full(r.size, 6 * i + d))
                    values.append(column[r])
        # A torus turned about its own axis moves no point off itself: the spin is a null direction of the loads
        # (without friction), pinned here by a stiffness as large as the largest of the matrix, so that no step
        # turns a ring about its axis (and the cap on each ring's move is not spent on it).
        axes = self.axes()
        pin = max(float(np.max(np.abs(np.concatenate(values)))) if values else 1.0, 1.0)
        block = (6 * np.arange(free.size)[:, None] + 3 + np.arange(3)).repeat(3, axis=1).ravel()
        rows.append(block)
        cols.append((6 * np.arange(free.size)[:, None] + 3 + np.tile(np.arange(3), 3)).ravel())
        values.append((pin * axes[:, :, None] * axes[:, None, :]).ravel())
        size = 6 * free.size
        return sparse.csc_matrix((np.concatenate(values), (np.concatenate(rows), np.concatenate(cols))),
                                 shape=(size, size))  # fmt: skip


def _preconditioner(problem, grad):
    """The solve x -> (H + sigma I)^(-1) x with H the symmetric part of the stiffness matrix at the base pose (its
    gradient there ``grad``), sigma the smallest of 1e-8, 1e-6, ... times its largest diagonal that makes it
    positive definite (:func:`_factor`), or None where no such shift is found (its matrix not finite)."""
    from scipy import sparse

    matrix = problem.stiffness(grad)
    symmetric = (0.5 * (matrix + matrix.T)).tocsc()
    size = symmetric.shape[0]
    largest = float(np.max(np.abs(symmetric.diagonal()), initial=0.0))
    if not np.isfinite(largest):  # no shift makes it finite (the checks of _factor refuse it)
        return None
    sigma = 1e-8 * max(largest, 1.0)
    while (factor := _factor(symmetric + sigma * sparse.identity(size))) is None:
        sigma *= 100.0
        if sigma > 1e8 * max(largest, 1.0):  # the shift dwarfs the matrix: no preconditioner left to keep
            return None
    return factor.solve


#: Largest normwise backward error of a solve by the factors of :func:`_factor` (its check): far above the rounding
#: of a stable factorisation (a small multiple of the machine's epsilon, at most its size times it: 1e-12 for 5,000
#: unknowns), far below that of factors SuperLU spoilt (of order one).
BACKWARD = 1e-8


def _factor(matrix, positive=True):
    """The sparse LU factors (SuperLU) of a matrix, or None where they are not to be trusted.

    ``positive``: the matrix is symmetric, factorised without pivoting off the diagonal, and refused where it is not
    positive definite (a pivot zero or negative: the pivots give its inertia); else with SuperLU's partial pivoting.
    Refused too: a matrix with an entry not finite, and factors whose solve of a probe (b = A 1) is not finite or
    has a backward error above ``BACKWARD``.  SuperLU checks neither: the 30 x 30 drape before these checks drew
    from inside it BLAS's complaints of an illegal leading dimension ("On entry to DTRSV parameter number 6 had an
    illegal value"), which BLAS prints and ignores, and went on with what it returned (module notes)."""
    from scipy.sparse.linalg import norm, splu

    matrix = matrix.tocsc()
    if not np.all(np.isfinite(matrix.data)):
        return None
    options = {"permc_spec": "MMD_AT_PLUS_A", "diag_pivot_thresh": 0.0, "options": {"SymmetricMode": True}}
    try:
        factor = splu(matrix, **(options if positive else {}))
    except RuntimeError:  # a pivot exactly zero
        return None
    if positive and not np.all(factor.U.diagonal() > 0.0):
        return None
    probe = matrix @ np.ones(matrix.shape[0])
    solution = factor.solve(probe)
    if not np.all(np.isfinite(solution)):
        return None
    scale = norm(matrix, np.inf) * np.max(np.abs(solution), initial=0.0) + np.max(np.abs(probe), initial=0.0)
    return factor if np.max(np.abs(matrix @ solution - probe), initial=0.0) <= BACKWARD * scale else None


def _descent(problem, tol, max_iterations):
    """The first phase of the module notes on ``problem``: L-BFGS on the energy, the loads its gradient, until
    max |gradient| <= tol, ``max_iterations`` accepted steps or a line search that finds no lower energy.  Returns
    the number of accepted steps."""
    size = 6 * problem.moving.size
    energy, grad = problem.evaluate(np.zeros(size))
    grad = problem.project(grad)
    scale = problem.weight * problem.length  # J per unit of gradient times step
    rounding = problem.rounding
    memory = []  # the last MEMORY pairs (step s, change of the gradient y, 1 / s.y)
    iterations, forced, gamma = 0, 0, None
    factor, built = None, -REFRESH  # the preconditioner (module notes) and the step it was built at
    while iterations < max_iterations and size and np.max(np.abs(grad)) > tol:
        if PRECONDITION and iterations - built >= REFRESH:
            factor, built = _preconditioner(problem, grad), iterations
        step = -grad
        ratios = []
        for s, y, rho in reversed(memory):  # the two-loop recursion (Nocedal and Wright, Algorithm 7.4)
            ratios.append(rho * (s @ step))
            step -= ratios[-1] * y
        if factor is not None:
            step = factor(step)  # the initial inverse Hessian: the stiffness matrix's
            if not np.all(np.isfinite(step)):  # factors that passed their probe but fail here: dropped till the
                factor, step = None, -grad  # next build (the step below then goes along the gradient)
        elif memory:
            s, y, rho = memory[-1]
            step *= 1.0 / (rho * (y @ y))  # the initial inverse Hessian s.y / y.y
        for (s, y, rho), a in zip(memory, reversed(ratios), strict=True):
            step += (a - rho * (y @ step)) * s
        step = problem.project(step)
        if not step @ grad < 0.0:  # not downhill (a preconditioner or pairs from before a minimum came or went)
            memory.clear()
            step = -grad
        largest = np.max(np.abs(step))
        if largest > STEP:
            step *= STEP / largest
        for _ in range(SEARCH):  # backtracking to Armijo's condition, or a smaller residual (as _newton accepts)
            trial_energy, trial_grad = problem.evaluate(step)  # searched from scratch (module notes)
            trial_grad = problem.project(trial_grad)
            if trial_energy - energy <= 1e-4 * scale * (step @ grad) + rounding or (
                np.linalg.norm(trial_grad) < np.linalg.norm(grad)
            ):
                forced = 0
                break
            step *= 0.5
        else:
            if memory:
                memory.clear()  # try the gradient
                continue
            # Neither a lower energy nor a lower residual along the gradient (rounding, or a minimum found or missed
            # next to a fold: module notes).  Follow the loads by a step of the smallest inverse curvature met
            # (overdamped motion, stable on the stiffest curvature), for at most FORCED steps in a row.
            forced += 1
            if gamma is None or forced > FORCED:
                break
            step = -gamma * grad
            largest = np.max(np.abs(step))
            if largest > STEP:
                step *= STEP / largest
            trial_energy, trial_grad = problem.evaluate(step)
            trial_grad = problem.project(trial_grad)
        iterations += 1
        # The energy at the new base (from which evaluate counts the weights' work); the gradient at the trial
        # serves as the base's (its torques differ by the left Jacobian of SO(3), second order in the step).
        energy = trial_energy - problem.g * float(
            np.sum(problem.masses[problem.moving] * step.reshape(-1, 6)[:, 2]) * problem.length
        )
        problem.move(step)
        change = trial_grad - grad
        grad = problem.project(trial_grad)
        curvature = float(step @ change)
        if curvature > 1e-12 * np.linalg.norm(step) * np.linalg.norm(change):
            memory.append((step, change, 1.0 / curvature))
            del memory[:-MEMORY]
            gamma = min(gamma or np.inf, curvature / float(change @ change))
    return iterations


def _newton(problem, tol, max_iterations):
    """The pseudo-transient Newton iterations of the module notes on ``problem`` until max |gradient| <= tol; returns
    the number of iterations (accepted or not)."""
    from scipy import sparse

    size = 6 * problem.moving.size
    energy, grad = problem.evaluate(np.zeros(size))
    rounding = problem.rounding
    tau, matrix = 1.0, None  # pseudo-time step: (I / tau + H) dx = -g
    residual = np.linalg.norm(grad)
    for iteration in range(max_iterations):
        if not size or np.max(np.abs(grad)) <= tol:
            return iteration
        if matrix is None:
            matrix = problem.stiffness(grad)
            symmetric = (0.5 * (matrix + matrix.T)).tocsc()
        shift = sparse.identity(size) / tau
        factor = _factor(symmetric + shift)
        if factor is None:
            tau *= 0.25
            continue
        step = factor.solve(-grad)
        if tau >= NEWTON:  # near the solution, the step of the matrix itself (symmetric but for its finite
            # differences): Newton's, quadratic; where its factors are refused, the symmetric step
            unsymmetric = _factor(matrix + shift, positive=False)
            newton = unsymmetric.solve(-grad) if unsymmetric is not None else step
            step = newton if np.all(np.isfinite(newton)) else step
        largest = np.max(np.abs(step))
        if not np.isfinite(largest):
            tau *= 0.25
            continue
        if largest > STEP:
            step *= STEP / largest
        trial_energy, trial_grad = problem.evaluate(step)
        change = trial_energy - energy
        if change <= rounding or np.linalg.norm(trial_grad) < residual:
            problem.move(step)
            energy, grad = problem.evaluate(np.zeros(size))
            new = np.linalg.norm(grad)
            tau = min(tau * max(residual / new, 0.5) * (2.0 if largest < STEP else 1.0), 1e12)
            residual, matrix = new, None
        else:
            tau *= 0.25
    return max_iterations


def _phase(name, problem, solver, *options):
    """Run ``solver(problem, *options)`` (returning its iterations) and record it: name, softening, iterations,
    evaluations of the loads, wall and CPU time (s), peak of the memory allocated (bytes, when tracemalloc traces;
    else None) and the largest residual after it (m g; torques m g R), from the last evaluation."""
    import time
    import tracemalloc

    evaluations, wall, cpu = problem.evaluations, time.perf_counter(), time.process_time()
    if tracemalloc.is_tracing():
        tracemalloc.reset_peak()
    iterations = solver(problem, *options)
    size = 6 * problem.moving.size
    _, grad = problem.evaluate(np.zeros(size), cold=False)
    return {
        "phase": name,
        "softening": problem.dynamics.stiffness_scale,
        "iterations": iterations,
        "evaluations": problem.evaluations - evaluations,
        "wall": time.perf_counter() - wall,
        "cpu": time.process_time() - cpu,
        "memory": tracemalloc.get_traced_memory()[1] if tracemalloc.is_tracing() else None,
        "residual": float(np.max(np.abs(problem.project(grad)))) if size else 0.0,
    }


def static_state(network, *, g=STANDARD_GRAVITY, force_tol=1e-8, max_iterations=200):
    """The static state of :func:`equilibrium` and the record of its phases, without its final check.

    Parameters
    ----------
    network, g, force_tol, max_iterations
        As :func:`equilibrium` (g in m/s^2, ``force_tol`` in weights m g).

    Returns
    -------
    centres : numpy.ndarray
        (n, 3), m.
    orientations : numpy.ndarray
        (n, 4) unit quaternions.
    phases : list of dict
        One per phase (the first-order descent, then Newton's method per stage): ``phase``, ``softening``,
        ``iterations``, ``evaluations`` (of the loads), ``wall`` and ``cpu`` (s), ``memory`` (peak bytes
        allocated, when :mod:`tracemalloc` traces; else None) and ``residual`` (the largest scaled load on a free
        ring after it, m g or m g R, from the warm-started search).
    """
    g = float(v.positive("g", g, "m/s^2"))
    force_tol = float(v.positive("force_tol", force_tol))
    max_iterations = v.count("max_iterations", max_iterations, 1)
    pose, phases = None, []
    for softening in SOFTENING:
        problem = _Problem(network, g, softening, pose)
        tol = force_tol if softening == 1.0 else max(force_tol, 1e-3)
        phases.append(_phase("descent", problem, _descent, max(tol, HANDOVER), DESCENT))
        if phases[-1]["residual"] > tol:
            best = problem.centres.copy(), problem.orientations.copy(), phases[-1]["residual"]
            phases.append(_phase("newton", problem, _newton, tol, max_iterations))
            if phases[-1]["residual"] > best[2]:  # Newton's steps can raise the residual (module notes)
                problem.centres, problem.orientations = best[0], best[1]
        pose = problem.centres, problem.orientations
    return problem.centres, problem.orientations, phases


def equilibrium(network, *, g=STANDARD_GRAVITY, force_tol=1e-8, max_iterations=200):
    """The network at its static state under gravity (along -z), its fixed rings held where they are.

    Parameters
    ----------
    network : Rings
        The rings, their law and anchors; its rest pose is the start.
    g : float
        Gravity, m/s^2 (> 0).
    force_tol : float
        Largest residual force on a free ring, as a fraction of the heaviest weight m g (torques: of m g R with
        R the largest major radius); the contact forces' own rounding, about 1e-10, is the floor.
    max_iterations : int
        Newton iterations of each stage (module notes), accepted or not.

    Returns
    -------
    Rings
        The same network (laws, anchors) at rest in its static state (:meth:`Rings.moved`).

    Raises
    ------
    RuntimeError
        If the residuals are still above ``force_tol`` at the end.
    """
    g = float(v.positive("g", g, "m/s^2"))
    force_tol = float(v.positive("force_tol", force_tol))
    centres, orientations, _ = static_state(network, g=g, force_tol=force_tol, max_iterations=max_iterations)
    _, forces, torques = network.potential(centres, orientations, g)  # every contact searched afresh
    moving = ~network.fixed
    weight = float(np.max(network.masses)) * g
    torque_scale = weight * max(ring.R for ring in network.rings)
    residual_force = float(np.max(np.abs(forces[moving]), initial=0.0))
    residual_torque = float(np.max(np.abs(torques[moving]), initial=0.0))
    if residual_force > force_tol * weight or residual_torque > force_tol * torque_scale:
        raise RuntimeError(f"no static state within {max_iterations} iterations: largest residual force "
                           f"{residual_force:.3g} N (goal {force_tol * weight:.3g} N), torque "
                           f"{residual_torque:.3g} N m (goal {force_tol * torque_scale:.3g} N m)")  # fmt: skip
    return network.moved(centres, orientations)
