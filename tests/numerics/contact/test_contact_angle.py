"""One contact at any angle (issue 24, items 3, 4 and 12): ringchain.numerics.contact_at_angle.

The closed-form Hertz ellipse where its long semi-axis stays within the half-space limit over the forces
asked for, the numerical contact of the exact gap elsewhere; the result says which, and whether the
contact it describes stays within the limit itself.
"""

import math

import numpy as np
import pytest
from ringchain.numerics import HALF_SPACE_LIMIT, contact_at_angle
from ringchain.theory import (
    bending_stiffness,
    contact_semi_axes,
    fit_power_law,
    hertz_stiffness,
    local_exponent,
    minimum_contact_angle,
    series_displacement,
)

R, r, E, nu = 22.5e-3, 2.5e-3, 193e9, 0.29  # the paper's R/r = 9 stainless ring
K_b = float(bending_stiffness(R, r, E, nu))
LOWEST = float(minimum_contact_angle(R, r))


def test_hertz_where_its_ellipse_stays_within_the_half_space():
    contact = contact_at_angle(R, r, E, nu, math.radians(60.0), K_b=K_b)
    assert contact.method == "hertz" and contact.curve is None and contact.within_half_space
    K_c = float(hertz_stiffness(R, r, E, nu, math.radians(60.0)))
    assert contact.K_c == K_c
    assert (contact.K, contact.n) == tuple(float(x) for x in fit_power_law(K_c=K_c, K_b=K_b))
    a, _ = contact_semi_axes(R, r, E, nu, math.radians(60.0), F=100.0)
    assert contact.extent_over_r == float(a) / r  # the long semi-axis at the top of the window
    F = np.array([1.0, 10.0, 300.0])  # any force, the window's or not
    np.testing.assert_array_equal(contact.extension(F), series_displacement(F, K_c=K_c, K_b=K_b))
    np.testing.assert_array_equal(contact.local_exponent(F), local_exponent(F, K_c=K_c, K_b=K_b))


def test_the_handover_is_where_the_ellipse_reaches_the_limit():
    contact = contact_at_angle(R, r, E, nu, math.radians(60.0), K_b=K_b)
    a, _ = contact_semi_axes(R, r, E, nu, contact.handover, F=100.0)
    # Root found to 1e-12 rad; a varies by a few per cent per degree there: 1e-9 is rounding.
    assert float(a) == pytest.approx(HALF_SPACE_LIMIT * r, rel=1e-9)
    assert LOWEST < contact.handover < math.radians(60.0)  # 55.8 deg for 1-100 N
    # A wider window moves the handover up: at 1000 N even the circle at 90 deg is 0.109 r.
    assert contact_at_angle(R, r, E, nu, math.pi / 2, K_b=K_b, window=(1.0, 30.0)).handover < contact.handover


def test_k_c_is_continuous_across_the_handover():
    handover = contact_at_angle(R, r, E, nu, math.pi / 2, K_b=K_b).handover
    above = contact_at_angle(R, r, E, nu, handover + 1e-4, K_b=K_b, n_forces=9)
    below = contact_at_angle(R, r, E, nu, handover - 1e-4, K_b=K_b, n_forces=9)
    assert (above.method, below.method) == ("hertz", "numerical")
    # At the handover the ellipse is 0.1 r long and the boundary elements reproduce Hertz to their grid's
    # 0.2 % (16 pixels across; the gap's quartic terms add < 0.1 %); measured 2e-4. Over 2e-4 rad K_c
    # changes by 1e-4.
    assert below.K_c == pytest.approx(above.K_c, rel=3e-3)
    assert below.n == pytest.approx(above.n, abs=1e-3)  # n in series with bending moves less than K_c
    assert below.extension(10.0) == pytest.approx(above.extension(10.0), rel=3e-3)
    assert below.extent_over_r == pytest.approx(above.extent_over_r, rel=0.05)  # pixel edges: 1/16 of a patch


def test_just_above_theta_min_the_numerical_contact_is_used_and_flagged():
    # The case: 8.8e10 at 39 deg from the single ellipse, 2.1e11 at 38.95, 4.2e12 at 38.94245 (it
    # grows without bound), then 8.7e10 from the numerical contact just below. The ellipse at 100 N is
    # then a line a tube radius long: not a Hertz contact.
    for angle_deg in (39.0, 38.94245):
        contact = contact_at_angle(R, r, E, nu, math.radians(angle_deg), K_b=K_b, n_forces=5)
        assert contact.method == "numerical"
        assert 5e10 < contact.K_c < 1e11  # 6.8e10 and 8.7e10 (boundary elements), never 4e12
        assert not contact.within_half_space and contact.extent_over_r > 0.5  # 0.57 r and 0.61 r at 100 N
        assert contact.limit_force < 1.0  # beyond the limit over the whole window


def test_a_numerical_patch_beyond_its_limit_is_flagged():
    contact = contact_at_angle(R, r, E, nu, math.radians(14.0), K_b=K_b, n_forces=7)
    assert contact.method == "numerical" and contact.n_patches == 2
    assert not contact.within_half_space and contact.extent_over_r == pytest.approx(0.188, rel=0.05)  # measured
    # The largest force within the limit, from the computed extents (0.1 r at about 18 N, measured).
    assert 10.0 < contact.limit_force < 30.0
    curve = contact.curve
    extent = np.exp(np.interp(np.log(contact.limit_force), np.log(curve.force), np.log(curve.extent)))
    assert extent == pytest.approx(HALF_SPACE_LIMIT * r, rel=1e-9)  # log-log interpolation, as computed


def test_forces_beyond_the_window_are_computed_not_refused():
    contact = contact_at_angle(R, r, E, nu, math.radians(30.0), K_b=K_b, window=(1.0, 30.0), n_forces=7,
                               forces=[60.0])  # fmt: skip
    assert contact.method == "numerical" and contact.within_half_space  # 0.08 r at 60 N
    assert contact.curve.force.max() == 60.0
    assert contact.extension(60.0) > contact.extension(30.0)
    with pytest.raises(ValueError, match=r"F must lie within the computed forces \[1, 60\] N"):
        contact.extension(100.0)


@pytest.mark.parametrize(("angle_deg", "window"), [(30.0, (1.0, 1e4)), (13.0, (1.0, 3000.0)), (20.0, (1.0, 1e5))])
def test_contacts_reaching_round_the_tube_are_refused_in_one_sentence(angle_deg, window):
    # The cases of item 12: "ray casting onto the torus did not converge" (a RuntimeError).
    with pytest.raises(ValueError, match=r"reaches round the tube at [0-9.e+]+ N") as refused:
        contact_at_angle(R, r, E, nu, math.radians(angle_deg), K_b=K_b, window=window, n_forces=5)
    assert "\n" not in str(refused.value)


def test_a_gap_that_curves_away_is_refused():
    # Issue 24, item 15: at 12.8 deg (just above 2 arcsin(r/R) = 12.76) the gap curves away from the contact
    # points across the bisector: no isolated contact, and "invalid value encountered in sqrt".
    with pytest.raises(ValueError, match=r"12\.8 deg .* curves away .* above about 12\.8[0-9] deg"):
        contact_at_angle(R, r, E, nu, math.radians(12.8), K_b=K_b)


def test_bad_arguments_name_the_problem():
    with pytest.raises(ValueError, match="F_min < F_max"):
        contact_at_angle(R, r, E, nu, 1.0, K_b=K_b, window=(100.0, 1.0))
    with pytest.raises(ValueError, match="K_b must be positive"):
        contact_at_angle(R, r, E, nu, 1.0, K_b=-1.0)
    with pytest.raises(TypeError):
        contact_at_angle(R, r, E, nu, 1.0, K_b)  # keyword-only, as the theory's chain parameters
