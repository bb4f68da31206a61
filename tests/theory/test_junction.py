"""The junction of two chains: impedance and the reflection and transmission of long linear waves."""

import numpy as np
import pytest
from ringchain.theory import impedance, junction_coefficients, linear, sound_speed
from ringchain.theory._codegen import sp


def test_junction_conserves_energy_and_keeps_the_force_continuous():
    R, T = linear.junction_symbolic()
    Z1, Z2 = sp.symbols("Z_1 Z_2", positive=True)
    assert sp.simplify(1 + R - T) == 0  # force continuous: incident + reflected = transmitted
    assert sp.simplify(R**2 + Z1 / Z2 * T**2 - 1) == 0  # energy fluxes F^2/Z balance
    assert R.subs(Z2, Z1) == 0 and T.subs(Z2, Z1) == 1  # no junction
    assert sp.limit(R, Z2, sp.oo) == 1 and sp.limit(T, Z2, 0) == 0  # a wall doubles the force; a free end drops it


def test_junction_coefficients_are_the_derived_ones():
    Z1, Z2 = np.array([1.0, 2.0, 5.0]), np.array([3.0, 2.0, 1.0])
    R, T = junction_coefficients(Z1, Z2)
    # Exact rational arithmetic of the closed form: rounding only.
    np.testing.assert_allclose(R, (Z2 - Z1) / (Z1 + Z2), rtol=1e-15, atol=1e-16)
    np.testing.assert_allclose(T, 2 * Z2 / (Z1 + Z2), rtol=1e-15)


@pytest.mark.parametrize("model", ["power-law", "dual-spring"])
def test_impedance_is_mass_times_sound_speed_over_spacing(model):
    K_b = 3.3e6 if model == "dual-spring" else None
    args = dict(model=model, F_0=np.array([0.5, 5.0, 50.0]), K=7.5e9, n=1.5, m=8e-3, a=0.04, K_b=K_b)
    Z = impedance(**args)
    k_c = 1.5 * 7.5e9 ** (2 / 3) * args["F_0"] ** (1 / 3)  # dF/d delta of K delta^1.5 at F_0
    k = k_c if K_b is None else k_c * K_b / (k_c + K_b)  # contact and ring body in series (Eq. 3)
    np.testing.assert_allclose(Z, np.sqrt(8e-3 * k), rtol=1e-13)  # a few roundings
    np.testing.assert_allclose(Z, 8e-3 * sound_speed(**args) / 0.04, rtol=1e-15)


BAD = [(0.0, 1.0, "Z1 must be positive"), (1.0, -2.0, "Z2 must be positive"), ([1.0, 2.0], [1.0, 2.0, 3.0], "Z1")]


@pytest.mark.parametrize(("Z1", "Z2", "message"), BAD)
def test_junction_coefficients_validate(Z1, Z2, message):
    with pytest.raises(ValueError, match=message):
        junction_coefficients(Z1, Z2)
