"""Ring, materials and the interlocking limits."""

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
