"""Ring, materials and the interlocking limits."""

import mpmath
import numpy as np
import pytest
from ringchain.theory import (
    MIN_CHAIN_ASPECT_RATIO,
    STAINLESS_STEEL_304,
    Material,
    Ring,
    bending_stiffness,
    get_material,
    hertz_stiffness,
)


def test_ring_quantities():
    ring = Ring.from_aspect_ratio(9.0)
    assert ring.R == pytest.approx(22.5e-3) and ring.r == pytest.approx(2.5e-3)
    assert ring.spacing == pytest.approx(2 * (22.5e-3 - 2.5e-3))
    # Torus volume by a midpoint sum over the tube cross-section (each annulus element carries its
    # circumference 2 pi rho): independent of Pappus; 2000^2 cells give 1e-6 relative accuracy.
    n = 2000
    y, z = np.meshgrid((np.arange(n) + 0.5) / n * 2 - 1, (np.arange(n) + 0.5) / n * 2 - 1)
    inside = y**2 + z**2 < 1
    rho = ring.R + ring.r * y
    volume = np.sum(2 * np.pi * rho * inside) * (2 * ring.r / n) ** 2
    assert ring.volume == pytest.approx(volume, rel=1e-3)  # pixelated disc edge: ~1e-4
    assert ring.mass == pytest.approx(STAINLESS_STEEL_304.rho * ring.volume)
    assert ring.K_c == pytest.approx(float(hertz_stiffness(ring.R, ring.r, 193e9, 0.29)))
    assert ring.K_b == pytest.approx(float(bending_stiffness(ring.R, ring.r, 193e9, 0.29)))
    assert ring.crossover_force == pytest.approx(ring.K_b**3 / ring.K_c**2)


def test_thin_option_and_angle():
    thin = Ring.from_aspect_ratio(9.0, thin=True)
    assert thin.K_b > Ring.from_aspect_ratio(9.0).K_b
    oblique = Ring.from_aspect_ratio(9.0, angle=np.radians(60))
    assert oblique.K_c > Ring.from_aspect_ratio(9.0).K_c


def test_chain_limit():
    assert MIN_CHAIN_ASPECT_RATIO == 3.0
    ring = Ring.from_aspect_ratio(2.5)  # two rings can interlock ...
    assert not ring.can_form_chain
    with pytest.raises(ValueError, match="cannot form a chain"):  # ... but not a chain
        ring.check_chain()
    Ring.from_aspect_ratio(3.1).check_chain()


def test_ring_rejects_non_hertzian_geometry():
    with pytest.raises(ValueError, match="R must exceed 2 r"):
        Ring.from_aspect_ratio(1.9)
    with pytest.raises(ValueError, match="single elliptical Hertz contact"):
        Ring.from_aspect_ratio(8.0, angle=np.radians(30))


def test_materials():
    assert get_material("stainless") is STAINLESS_STEEL_304
    assert "304" in STAINLESS_STEEL_304.source
    assert STAINLESS_STEEL_304.G == pytest.approx(193e9 / (2 * 1.29))
    with pytest.raises(ValueError, match="unknown material"):
        get_material("unobtainium")
    with pytest.raises(ValueError, match="nu must lie in"):
        Material("bad", E=1e9, nu=0.7, rho=1000.0, source="none")


def test_contact_modulus_is_johnsons():
    # Johnson, Contact Mechanics, Eq. (4.22) (App. A of the paper): 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2,
    # here with two bodies of one material, typed and evaluated by mpmath.
    for material in (STAINLESS_STEEL_304, Material("soft", E=3e6, nu=0.49, rho=1100.0, source="test")):
        with mpmath.workdps(30):
            E, nu = mpmath.mpf(material.E), mpmath.mpf(material.nu)
            expected = 1 / (2 * (1 - nu**2) / E)
        assert material.E_star == pytest.approx(float(expected), rel=1e-15)  # a few roundings


def test_hertz_stiffness_uses_the_materials_contact_modulus():
    # Paper Eq. (1), K_c = 4/3 E* sqrt(R_e), R_e = r(R - r)/(R - 2r), with the Material's own E*.
    ring = Ring.from_aspect_ratio(9.0)
    R_e = ring.r * (ring.R - ring.r) / (ring.R - 2 * ring.r)
    assert ring.K_c == pytest.approx(4 / 3 * ring.material.E_star * np.sqrt(R_e), rel=1e-14)


def test_thin_must_be_a_boolean():
    for value in ("no", "yes", 1, None):
        with pytest.raises(TypeError, match="thin must be True or False"):
            Ring.from_aspect_ratio(9.0, thin=value)
    assert Ring.from_aspect_ratio(9.0, thin=np.bool_(False)).thin is False


def test_chain_limit_within_rounding_and_message_digits():
    # 0.3/0.1 = 2.9999999999999996 in floating point: the limiting ring R = 3 r, not a refusal.
    assert Ring(0.3, 0.1).can_form_chain
    Ring(0.3, 0.1).check_chain()
    with pytest.raises(ValueError, match=r"R/r = 2\.99999989\d* is below 3"):  # every digit, no "3 < 3"
        Ring(0.29999999, 0.1).check_chain()


def test_ring_of_extreme_size_gives_a_value_error():
    # The torus volume r^2 once raised OverflowError from Python's float power.
    with pytest.raises(ValueError, match="not representable"):
        Ring(3e200, 1e200)


def test_ring_and_material_take_single_numbers():
    with pytest.raises(ValueError, match="R of a Ring must be one number"):
        Ring(np.array([20e-3, 22e-3]), 2.5e-3)
    with pytest.raises(ValueError, match="E of a material must be one number"):
        Material("x", E=[1e9, 2e9], nu=0.3, rho=1000.0, source="test")
