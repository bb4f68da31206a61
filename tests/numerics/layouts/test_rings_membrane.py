"""The point model's membrane beside rigid rings (numerics/layouts/rings_membrane.py), and the tilted chain of
rings_layouts: what the chapter "Rings in space" measures with them."""

import numpy as np
import pytest
from ringchain.numerics import Rings, simulate, torus_contacts
from ringchain.numerics.layouts.rings_layouts import chain_layout, tilted_chain_layout
from ringchain.numerics.layouts.rings_membrane import link_forces_at_rest, membrane_deflection, taut_chain
from ringchain.theory import STANDARD_GRAVITY, Ring

RING = Ring.from_aspect_ratio(9.0)  # the paper's ring: R = 22.5 mm, r = 2.5 mm, steel


def string(n_points, a):
    """A straight string of n_points along x, a apart, its two ends fixed."""
    centres = np.column_stack([np.arange(n_points) * a, np.zeros(n_points), np.zeros(n_points)])
    links = np.column_stack([np.arange(n_points - 1), np.arange(1, n_points)])
    return centres, links


def test_membrane_of_a_beaded_string_is_the_closed_form():
    # N beads carrying P each between two fixed ends, N + 1 links of length a and tension T: the bead k's
    # equilibrium T (2 w_k - w_{k-1} - w_{k+1}) / a = P gives w_k = P a k (N + 1 - k) / (2 T) (by hand: the
    # second difference of a parabola).
    N, a, T, P = 9, 0.04, 25.0, 0.2
    centres, links = string(N + 2, a)
    loads = np.full(N + 2, P)
    w = membrane_deflection(centres, links, np.full(N + 1, T), loads, fixed=[0, N + 1])
    k = np.arange(N + 2)
    # 1e-12: a 9 x 9 solve of a well-conditioned matrix, rounding only.
    np.testing.assert_allclose(w, P * a * k * (N + 1 - k) / (2 * T), rtol=1e-12, atol=1e-18)


def test_membrane_takes_a_mask_and_ignores_the_loads_of_fixed_points():
    centres, links = string(5, 0.04)
    mask = np.array([True, False, False, False, True])
    by_mask = membrane_deflection(centres, links, np.full(4, 10.0), [5.0, 0.0, 1.0, 0.0, 5.0], fixed=mask)
    by_index = membrane_deflection(centres, links, np.full(4, 10.0), [0.0, 0.0, 1.0, 0.0, 0.0], fixed=[0, 4])
    np.testing.assert_array_equal(by_mask, by_index)
    assert by_mask[0] == by_mask[4] == 0.0


@pytest.mark.parametrize(
    ("tensions", "fixed", "message"),
    [([10.0, -1.0, 10.0, 10.0], [0, 4], "tensions"), ([10.0] * 4, [], "at least one"),
     ([10.0, 0.0, 10.0, 10.0], [0], "not held"), ([10.0] * 3, [0, 4], "n_links")],
)  # fmt: skip
def test_membrane_rejects_what_it_cannot_solve(tensions, fixed, message):
    centres, links = string(5, 0.04)
    with pytest.raises(ValueError, match=message):
        membrane_deflection(centres, links, tensions, np.ones(5), fixed=fixed)


def test_taut_chain_carries_its_pretension():
    # Without gravity the taut chain is at rest: every contact carries the pretension.  The rings' contact takes
    # K_c from the curvatures at the contact, the layout from hertz_stiffness at 90 degrees (Eq. (1)); the two
    # agree to 1e-6 (the static pull's accuracy, tests/numerics/layouts/test_rings_dynamics.py).
    chain = taut_chain(6, RING, 30.0)
    assert chain.links.tolist() == [[0, 1], [1, 2], [2, 3], [3, 4], [4, 5]]
    assert chain.fixed.tolist() == [True, False, False, False, False, True]
    np.testing.assert_allclose(link_forces_at_rest(chain), 30.0, rtol=1e-6)
    _, forces, torques = chain.potential(chain.centres, chain.orientations, g=0.0)
    # Each free ring is held by two equal and opposite pulls along the axis through its centre: zero net force
    # and torque to the rounding of 30 N (1e-9 N, and 1e-9 N times R).
    assert np.abs(forces[~chain.fixed]).max() < 1e-9
    assert np.abs(torques[~chain.fixed]).max() < 1e-9 * RING.R


def test_taut_chain_rejects_a_law_it_cannot_pretension():
    with pytest.raises(ValueError, match="Hertz"):
        taut_chain(5, RING, 10.0, law="power-law")
    with pytest.raises(ValueError, match="tension"):
        taut_chain(5, RING, 0.0)


def test_taut_rings_sag_in_proportion_to_their_tension_and_less_than_the_string():
    # The chapter's claim: a taut chain of rigid rings sagging under its weight, against the point model's
    # membrane with the same tensions and loads.  Both are linear in 1/T for sags much smaller than the span
    # (w/L ~ 3e-3 here), so their ratio must not depend on the pretension; and the rings sag less than the string.
    ratios = []
    for pretension in (20.0, 320.0):
        taut = taut_chain(7, RING, pretension)
        rest = taut.equilibrium(force_tol=1e-6)
        tensions = link_forces_at_rest(rest)
        w = membrane_deflection(rest.centres, rest.links, tensions, rest.masses * STANDARD_GRAVITY, rest.fixed)
        sag = taut.centres[:, 2] - rest.centres[:, 2]
        ratios.append(sag[1:-1] / w[1:-1])
    # 1e-3: second-order effects of the sag on the geometry (the tensions change along the chain by (w/L)^2 and
    # the sagged links turn), measured 2.7e-4 at most over 7-15 rings.
    np.testing.assert_allclose(ratios[0], ratios[1], rtol=1e-3)
    assert np.all((ratios[0] > 0.0) & (ratios[0] < 0.9))  # stiffer than the string everywhere (measured 0.44-0.69)


def test_tilted_chain_without_tilt_is_the_straight_chain():
    straight = chain_layout(5, RING)
    same = tilted_chain_layout(5, RING, tilt=0.0, offset=0.0, seed=1)
    for a, b in zip(straight, same, strict=True):
        np.testing.assert_allclose(a, b, rtol=0, atol=1e-12)  # the z found by bisection to 1e-13 m


def test_tilted_chain_just_touches_and_is_seeded():
    centres, orientations, links = tilted_chain_layout(6, RING, tilt=np.radians(3.0), offset=0.5e-3, seed=29)
    again = tilted_chain_layout(6, RING, tilt=np.radians(3.0), offset=0.5e-3, seed=29)[0]
    np.testing.assert_array_equal(centres, again)
    assert np.abs(centres[:, :2]).max() <= 0.5e-3 and np.abs(centres[:, :2]).max() > 0.0
    for i, j in links:
        gap = torus_contacts(centres[i], orientations[i], RING, centres[j], orientations[j], RING, margin=np.inf).gap
        assert abs(gap.min()) < 1e-12  # brentq's xtol, 1e-13 m, on a gap that changes about as fast as z
    with pytest.raises(ValueError, match="tilt"):
        tilted_chain_layout(6, RING, tilt=0.5, offset=0.0, seed=0)


def test_a_tilted_chain_struck_along_its_axis_turns_and_friction_turns_it_less():
    # The chapter's claim (its 16 rings for 1 ms, here 8 for 0.35 ms, the pulse's transit): the perfect chain
    # takes no energy into rotation (by symmetry, tests/numerics/layouts/test_rings_dynamics.py); a chain tilted by
    # up to 3 degrees does, and with friction less.
    centres, orientations, _ = tilted_chain_layout(8, RING, tilt=np.radians(3.0), offset=0.5e-3, seed=29)
    t = np.linspace(0.0, 3.5e-4, 71)
    rotation = {}
    for mu in (0.0, 0.3):
        rings = Rings.from_rings(centres, orientations, RING, friction=mu)
        sim = simulate(rings, t[-1], impact_velocity=0.5, gravity=False, t_eval=t, rtol=1e-9)
        energy = sim.energy()
        impact = energy.total[0]
        # The budget with the friction loss closes to 1e-5 of the impact energy: the Hertz law takes K_c from the
        # curvatures at each contact, which change with the pose, so its force is not exactly the gradient of its
        # energy (test_rings_dynamics); tilted rings slide over more curvature than rattling ones, measured 1.5e-6
        # here and 4e-6 on the chapter's 16 rings, the integration at rtol 1e-9 adding less than 1e-8.
        assert np.ptp(energy.total) <= 1e-5 * impact
        rotation[mu] = energy.rotational[-1] / impact
    assert rotation[0.0] > 1e-2  # per cent of the energy, where the perfect chain has none to round-off (1e-29)
    assert rotation[0.3] < rotation[0.0]
