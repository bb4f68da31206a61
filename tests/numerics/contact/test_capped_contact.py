"""The contact with its pressure capped at the first-yield pressure (numerics/contact_bem.py,
capped_contact_curve) against Thornton's loading curve (theory/plastic.py)."""

import numpy as np
import pytest
from ringchain.numerics.contact.plastic import CAPPED_KKT_TOLERANCE, capped_contact_curve
from ringchain.theory import equivalent_radius

R, r, E, NU, Y = 22.5e-3, 2.5e-3, 193e9, 0.29, 215e6  # the paper's ring, annealed AISI 304
RATIOS = [0.5, 2.0, 10.0, 300.0]


@pytest.fixture(scope="module")
def sphere():
    return capped_contact_curve(R, r, E, NU, Y, RATIOS, shape="sphere", pixels=32)


@pytest.fixture(scope="module")
def torus():
    return capped_contact_curve(R, r, E, NU, Y, RATIOS, shape="torus", pixels=32)


def test_every_solution_satisfies_the_contact_conditions(sphere, torus):
    for curve in (sphere, torus):
        assert np.all(curve.kkt_error <= CAPPED_KKT_TOLERANCE)


def test_elastic_below_yield(sphere, torus):
    # Below delta_y no pixel reaches the cap: the Hertz force.  32 pixels across resolve it to 0.1 %
    # (0.08 % measured against 128 pixels), and the torus gap's quartic terms add 1e-4 at 0.5 delta_y.
    for curve in (sphere, torus):
        assert curve.ratio[0] == pytest.approx(1.0, abs=2e-3)
        assert curve.plastic_area[0] == 0.0


def test_gap_to_thornton_grows_with_the_approach(sphere, torus):
    # Measured on 32-128 pixels (sphere and torus): 1.088-1.091 at 2 delta_y, 1.42-1.45 at 10 delta_y and
    # 1.83-1.88 at 300 delta_y; the bands below hold that spread (grid resolution, about 1-2 %).
    for curve in (sphere, torus):
        assert curve.ratio[1] == pytest.approx(1.09, abs=0.01)
        assert curve.ratio[2] == pytest.approx(1.44, abs=0.02)
        assert 1.8 < curve.ratio[3] < 2.0
        assert np.all(np.diff(curve.ratio) > 0)


def test_the_reason_is_the_contact_radius(sphere):
    # Thornton keeps Hertz's radius, a^2 = R_e delta (area pi R_e delta); the capped half-space spreads towards
    # the rigid truncation, a^2 = 2 R_e delta, as the flowing region takes over the contact.
    R_e = float(equivalent_radius(R, r))
    hertz_area = np.pi * R_e * sphere.delta
    spread = sphere.area / hertz_area
    assert spread[0] == pytest.approx(1.0, abs=0.1)  # elastic: Hertz's area, to the pixels on its edge
    assert np.all(np.diff(spread) > 0) and 1.8 < spread[-1] <= 2.0 + 0.1  # edge pixels (32 across: ~0.1)
    plastic_share = sphere.plastic_area / sphere.area
    assert plastic_share[-1] > 0.9  # at 300 delta_y nearly all of the contact flows
    # Force ~ p_y x area at large approach: the ratio to Thornton follows the area.
    assert sphere.force[-1] == pytest.approx(sphere.p_y * sphere.area[-1], rel=0.05)


def test_oblique_contact():
    # An elliptical contact (60 degrees): the same picture, capped at its own first-yield pressure.
    curve = capped_contact_curve(R, r, E, NU, Y, [0.5, 10.0], angle=np.radians(60), pixels=24)
    assert curve.ratio[0] == pytest.approx(1.0, abs=5e-3)  # 24 pixels across the short axis: 0.3 %
    assert 1.3 < curve.ratio[1] < 1.6


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (dict(shape="cube"), "shape must be one of"),
        (dict(pixels=4), "pixels must be at least 8"),
        (dict(angle=0.3), "theta_min"),
    ],
)
def test_bad_input_is_refused(kwargs, message):
    with pytest.raises(ValueError, match=message):
        capped_contact_curve(R, r, E, NU, Y, [1.0], **kwargs)
