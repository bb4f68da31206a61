"""FFT boundary elements and Polonsky and Keer's solver (numerics/contact/halfspace.py) against quadrature,
direct summation and closed forms (Boussinesq, Hertz, the flat punch)."""

import itertools

import numpy as np
import pytest
from ringchain.numerics.contact.halfspace import ElasticHalfSpace, rectangle_displacement
from scipy.integrate import dblquad

E_STAR = 1.1e11  # Pa
HX, HY = 2e-6, 3e-6  # a non-square pixel, m


def _boussinesq_over_pixel(x, y, a, b):
    """Integral of 1/(pi E* rho) over |xi| < a, |eta| < b seen from (x, y), by adaptive quadrature.

    The rectangle is cut at the point where it lies inside, so that the integrable 1/rho singularity
    sits at a corner of each piece.
    """
    xs = sorted({-a, a} | ({x} if -a < x < a else set()))
    ys = sorted({-b, b} | ({y} if -b < y < b else set()))
    total = 0.0
    for x0, x1 in itertools.pairwise(xs):
        for y0, y1 in itertools.pairwise(ys):
            value, _ = dblquad(
                lambda eta, xi: 1.0 / np.hypot(x - xi, y - eta), x0, x1, y0, y1, epsabs=0.0, epsrel=1e-11
            )
            total += value
    return total / (np.pi * E_STAR)


@pytest.mark.parametrize(
    "offset",
    [(0.0, 0.0), (0.3, -0.2), (0.5, 0.0), (1.0, 0.0), (0.0, 1.0), (3.0, -2.0), (-7.5, 11.0)],
    ids=["centre", "inside", "edge", "next-x", "next-y", "near", "far"],
)
def test_love_rectangle_equals_quadrature_of_boussinesq(offset):
    x, y = offset[0] * HX, offset[1] * HY
    love = float(rectangle_displacement(x, y, HX / 2, HY / 2, E_STAR))
    # The quadrature is asked for 1e-11 relative per piece; 1e-9 leaves room for its error estimate.
    assert love == pytest.approx(_boussinesq_over_pixel(x, y, HX / 2, HY / 2), rel=1e-9)


def test_far_from_the_pixel_it_is_a_point_load():
    rho = 1000 * HX
    love = float(rectangle_displacement(rho * 0.6, rho * 0.8, HX / 2, HY / 2, E_STAR))
    point = HX * HY / (np.pi * E_STAR * rho)  # Boussinesq: P/(pi E* rho) with P = 1 Pa x the pixel's area
    # The multipoles neglected by the point load are of relative order (size/rho)^2 ~ 1e-6.
    assert love == pytest.approx(point, rel=1e-5)


def test_fft_convolution_equals_the_direct_sum():
    nx, ny = 7, 5
    space = ElasticHalfSpace((nx, ny), (nx * HX, ny * HY), E_STAR)
    forces = np.random.default_rng(3).uniform(0.0, 1.0, (nx, ny))
    direct = np.zeros((nx, ny))
    for i in range(nx):
        for j in range(ny):
            for k in range(nx):
                for m in range(ny):
                    kernel = rectangle_displacement((i - k) * HX, (j - m) * HY, HX / 2, HY / 2, E_STAR)
                    direct[i, j] += forces[k, m] * float(kernel) / (HX * HY)
    # Both sum the same terms; the FFT's rounding is a few eps of the largest value.
    assert space.displacement(forces) == pytest.approx(direct, rel=1e-12, abs=1e-12 * direct.max())


def _sphere(n, radius, load, *, window=3.0):
    """A sphere of radius ``radius`` on a flat under ``load``: the half-space, the gap and Hertz's a, delta."""
    a = (3 * load * radius / (4 * E_STAR)) ** (1 / 3)  # Hertz (Johnson Sec. 4.2), typed independently
    space = ElasticHalfSpace((n, n), (window * a, window * a), E_STAR)
    X, Y = space.coordinates()
    return space, X, Y, (X**2 + Y**2) / (2 * radius), a, a**2 / radius


def test_force_control_on_a_sphere_gives_hertz():
    radius, load = 1e-2, 2.0
    space, X, Y, gap, a, delta = _sphere(64, radius, load)
    solution = space.solve(gap, load=load, pentol=1e-9 * delta, forcetol=1e-12 * load)
    assert solution.force == pytest.approx(load, rel=1e-12)  # force control holds the total exactly
    # 21 pixels across the contact radius: measured -6e-5 (-2.8e-4 with 11 pixels, -2.2e-5 with 43: it
    # falls about as h^2); 3e-4 holds it with room.
    assert solution.approach == pytest.approx(delta, rel=3e-4)
    w = solution.forces / load
    # Hertz's pressure has <x^2 + y^2> = 2 a^2/5; on the grid to (h/a)^2 ~ 0.2 %.
    assert np.sqrt(2.5 * np.sum(w * (X**2 + Y**2))) == pytest.approx(a, rel=5e-3)
    # The contact conditions hold to the requested tolerance: zero gap under load, none elsewhere negative.
    inside = solution.forces > 0
    assert np.max(np.abs(solution.separation[inside])) <= 1e-9 * delta
    assert np.min(solution.separation[~inside]) >= -1e-9 * delta
    assert not solution.flowing.any()


def test_displacement_control_inverts_force_control():
    space, _X, _Y, gap, _a, delta = _sphere(48, 5e-3, 0.7)
    by_force = space.solve(gap, load=0.7, pentol=1e-10 * delta, forcetol=1e-12)
    by_approach = space.solve(gap, approach=by_force.approach, pentol=1e-10 * delta, forcetol=1e-12)
    # Both solve the same problem with gaps within pentol = 1e-10 delta: the pixel forces differ by at most
    # 4 pentol/K00 (see the hardness test below), and the total by the pixels in contact times that.
    bound = 4 * 1e-10 * delta / space.self_influence
    assert by_approach.forces == pytest.approx(by_force.forces, abs=bound)
    assert by_approach.force == pytest.approx(0.7, abs=bound * np.count_nonzero(by_force.forces))


def test_a_rough_surface_of_many_contacts():
    # Polonsky and Keer's own use: a random surface (seeded, smoothed over a few pixels) pressed onto a flat,
    # touching in dozens of separate spots that merge and split as the load grows.
    from scipy import ndimage

    n = 48
    space = ElasticHalfSpace((n, n), (1e-3, 1e-3), E_STAR)
    heights = ndimage.gaussian_filter(np.random.default_rng(7).normal(size=(n, n)), 1.0, mode="wrap")
    gap = 2e-6 * heights / heights.std()
    gap -= gap.min()
    pentol = 1e-12  # m, a millionth of the roughness
    bound = 4 * pentol / space.self_influence  # the force difference of two solutions (hardness test below)
    spots = []
    for load in (10.0, 100.0, 1000.0):
        by_force = space.solve(gap, load=load, pentol=pentol, forcetol=1e-12 * load)
        by_approach = space.solve(gap, approach=by_force.approach, pentol=pentol, forcetol=1e-12 * load)
        touching = by_force.forces > 0
        assert np.max(np.abs(by_force.separation[touching])) <= pentol
        assert np.min(by_force.separation[~touching]) >= -pentol
        assert by_approach.forces == pytest.approx(by_force.forces, abs=bound)
        spots.append(ndimage.label(touching)[1])
    assert spots == sorted(spots) and spots[0] > 3 and spots[-1] > 20  # measured 12, 37, 65 spots


def test_a_hardness_above_the_peak_pressure_changes_nothing():
    radius, load = 1e-2, 2.0
    space, _X, _Y, gap, a, delta = _sphere(48, radius, load)
    free = space.solve(gap, approach=delta, pentol=1e-10 * delta, forcetol=1e-12)
    peak = 3 * load / (2 * np.pi * a**2)  # Hertz's p0
    capped = space.solve(gap, approach=delta, hardness=1.5 * peak * space.pixel_area, pentol=1e-10 * delta,
                         forcetol=1e-12)  # fmt: skip
    assert not capped.flowing.any()
    # Two solutions with gaps within pentol = 1e-10 delta differ in force by at most 2 pentol over the grid's
    # smallest stiffness eigenvalue, the checkerboard's, 0.52 times the self-influence (measured): 4 pentol/K00.
    assert capped.forces == pytest.approx(free.forces, abs=4 * 1e-10 * delta / space.self_influence)


def test_a_small_hardness_gives_the_bearing_area():
    # A hardness so small that the elastic displacements are negligible: every pixel the rigid surfaces
    # overlap flows, and the force is the hardness times their number (the rigid-plastic limit).
    space, _X, _Y, gap, _a, delta = _sphere(40, 1e-2, 2.0)
    hardness = 1e-9 * delta / space.self_influence  # the largest displacement is below 1e-9 delta x 40^2
    solution = space.solve(gap, approach=delta, hardness=hardness, pentol=1e-4 * delta, forcetol=1e-6 * hardness)
    overlap = gap < delta
    assert np.array_equal(solution.flowing, overlap)
    assert solution.force == pytest.approx(hardness * np.count_nonzero(overlap), rel=1e-12)


def test_a_capped_sphere_meets_the_contact_conditions():
    radius, load = 1e-2, 2.0
    space, _X, _Y, gap, a, delta = _sphere(48, radius, load)
    cap = 0.6 * 3 * load / (2 * np.pi * a**2) * space.pixel_area  # 60 % of Hertz's peak pressure
    solution = space.solve(gap, approach=2 * delta, hardness=cap, pentol=1e-8 * delta, forcetol=1e-9 * cap)
    h, f = solution.separation, solution.forces
    flowing, elastic = solution.flowing, (f > 0) & ~solution.flowing
    assert flowing.any() and elastic.any()
    assert np.all(f <= cap) and np.all(f >= 0)
    assert np.max(np.abs(h[elastic])) <= 1e-8 * delta  # the solver's tolerance
    assert np.max(h[flowing]) <= 1e-8 * delta and np.min(h[f == 0]) >= -1e-8 * delta
    # The elastic part is a fresh convolution of the forces (not the solver's running displacement).
    assert h == pytest.approx(gap + space.displacement(f) - 2 * delta, abs=1e-12 * delta)


@pytest.mark.parametrize("n", [32, 64])
def test_flat_punch_converges_to_boussinesq(n):
    # A rigid flat circular punch: F = 2 a E* delta (Boussinesq; Johnson, Contact Mechanics, Ch. 3).  On
    # pixels the punch is the pixelated disc, of radius a_eff = sqrt(area/pi); the edge's square-root
    # singularity leaves an error of first order in h, measured -0.23/n (16 to 128 pixels across).
    a, delta = 1e-3, 1e-6
    space = ElasticHalfSpace((n, n), (2 * a, 2 * a), E_STAR)
    X, Y = space.coordinates()
    punch = X**2 + Y**2 < a**2
    gap = np.where(punch, 0.0, 1.0)  # off the punch the surfaces never meet
    solution = space.solve(gap, approach=delta, pentol=1e-9 * delta, forcetol=1e-12)
    a_eff = np.sqrt(np.count_nonzero(punch) * space.pixel_area / np.pi)
    error = solution.force / (2 * a_eff * E_STAR * delta) - 1
    assert -0.35 / n < error < -0.15 / n


def test_no_overlap_no_force():
    space, _X, _Y, gap, _a, _delta = _sphere(16, 1e-2, 1.0)
    solution = space.solve(gap, approach=-1e-9, pentol=1e-12, forcetol=1e-12)
    assert solution.force == 0.0 and np.all(solution.separation > 0)


def test_bad_input_and_no_convergence_are_refused():
    space, _X, _Y, gap, _a, delta = _sphere(16, 1e-2, 1.0)
    tol = dict(pentol=1e-9 * delta, forcetol=1e-12)
    with pytest.raises(ValueError, match="exactly one of load"):
        space.solve(gap, **tol)
    with pytest.raises(ValueError, match="exactly one of load"):
        space.solve(gap, load=1.0, approach=delta, **tol)
    with pytest.raises(ValueError, match="needs displacement control"):
        space.solve(gap, load=1.0, hardness=1.0, **tol)
    with pytest.raises(ValueError, match="grid's shape"):
        space.solve(gap[1:], load=1.0, **tol)
    with pytest.raises(ValueError, match="load"):
        space.solve(gap, load=-1.0, **tol)
    with pytest.raises(ValueError, match="initial_forces"):
        space.solve(gap, load=1.0, initial_forces=-np.ones(gap.shape), **tol)
    with pytest.raises(ValueError, match="a"):
        rectangle_displacement(0.0, 0.0, -1.0, 1.0, E_STAR)
    with pytest.raises(RuntimeError, match="did not converge"):
        space.solve(gap, load=1.0, maxiter=2, **tol)
