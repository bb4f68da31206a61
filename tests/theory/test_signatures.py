"""One positional order and one spelling across the theory's public functions (issue 24, item 7).

The convention (module docstring of :mod:`ringchain.theory`): the quantity a function is evaluated at
comes first and may be positional (a force, a speed, a wavenumber, a position); the geometry and
material of the contact (R, r, E, nu, angle) follow positionally, because every swap among them is
refused by validation; everything that describes the chain or the contact law (F_0 where it is not
the variable, K, n, m, a, K_c, K_b, rho, ...) is keyword-only, so that a copied argument order can
never pass silently.  A static force is spelled F_0 everywhere (never F0).
"""

import inspect

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain import theory
from ringchain.theory import curved_beam

SETTINGS = settings(max_examples=40, deadline=None, derandomize=True)

#: Parameters that must be keyword-only wherever they are not a function's first parameter, in the one
#: order they appear in whenever several of them do.
CHAIN_ORDER = ("F_0", "K", "n", "m", "a", "K_c", "K_b", "m_striker", "rho")

#: Spellings that must not appear (the left one), with the one used instead.
RETIRED = {"F0": "F_0"}


def _public_functions():
    functions = [(f"theory.{name}", getattr(theory, name)) for name in theory.__all__]
    functions += [(f"curved_beam.{name}", getattr(curved_beam, name)) for name in ("element_matrices",)]
    return [(name, f) for name, f in functions if inspect.isfunction(f)]


@pytest.mark.parametrize(("name", "function"), _public_functions(), ids=[n for n, _ in _public_functions()])
def test_chain_parameters_are_keyword_only_in_one_order(name, function):
    parameters = list(inspect.signature(function).parameters.values())
    for position, p in enumerate(parameters):
        assert p.name not in RETIRED, f"{name} spells {p.name}; the package spells it {RETIRED[p.name]}"
        if p.name in CHAIN_ORDER and position > 0:
            assert p.kind is inspect.Parameter.KEYWORD_ONLY, f"{name}: {p.name} must be keyword-only"
    ordered = [p.name for p in parameters if p.name in CHAIN_ORDER]
    assert ordered == sorted(ordered, key=CHAIN_ORDER.index), f"{name}: chain parameters in the order {ordered}"


def test_material_fields_are_keyword_only():
    # E and rho are both positive numbers: Material("x", 8000.0, 0.29, 193e9, "") would pass silently.
    with pytest.raises(TypeError):
        theory.Material("x", 193e9, 0.29, 8000.0, "source")
    steel = theory.Material("x", E=193e9, nu=0.29, rho=8000.0, source="source")
    assert steel.E == 193e9


def test_copied_orders_raise_instead_of_answering():
    """The issue's case: impact_amplitude(v0, K, n, m, a) and solitary_wave_speed(F_m, K, n, a, m) had
    different orders, and copying one into the other gave 165.6 N instead of 121.6 N without an error."""
    K, n, m, a = 4.9e6, 1.11, 0.37 * 8.2e-3, 0.04
    with pytest.raises(TypeError):
        theory.impact_amplitude(1.0, K, n, a, m)
    with pytest.raises(TypeError):
        theory.solitary_wave_speed(10.0, K, n, m, a)
    with pytest.raises(TypeError):
        theory.linear_sound_speed(1.0, K, n, m, a)
    with pytest.raises(TypeError):
        theory.series_displacement(10.0, 7.5e9, 3.3e6)
    with pytest.raises(TypeError):  # the retired spelling is an error, not an ignored keyword
        theory.sound_speed(F0=1.0, model="power-law", K=K, n=n, m=m, a=a)
    # The keyword call is the same whatever order the keywords are written in.
    F_m = theory.impact_amplitude(1.0, K=K, n=n, m=m, a=a)
    assert F_m == theory.impact_amplitude(1.0, a=a, m=m, n=n, K=K)
    assert theory.solitary_wave_speed(F_m, K=K, n=n, m=m, a=a) == theory.solitary_wave_speed(F_m, a=a, m=m, K=K, n=n)


# --- why the geometry may stay positional: every swap is refused ---------------------------------


@SETTINGS
@given(
    r=st.floats(-6, -1).map(lambda x: 10.0**x),
    aspect=st.floats(2.01, 100.0),
    E=st.floats(6, 12).map(lambda x: 10.0**x),
    nu=st.floats(0.0, 0.49),
)
def test_positional_geometry_swaps_are_refused(r, aspect, E, nu):
    R = aspect * r
    swaps = [
        lambda: theory.hertz_stiffness(r, R, E, nu),
        lambda: theory.hertz_stiffness(R, r, nu, E),
        lambda: theory.contact_ellipse(r, R),
        lambda: theory.minimum_contact_angle(r, R),
        lambda: theory.bending_stiffness(r, R, E, nu),
        lambda: theory.bending_stiffness(R, r, nu, E),
        lambda: theory.hertz_stiffness_pair(r, R, E, nu, R, r, E, nu),
        lambda: theory.ring_frequencies(r, R, E, nu, rho=8000.0, k=2),
        lambda: theory.ring_frequencies(R, r, nu, E, rho=8000.0, k=2),
    ]
    for swapped in swaps:
        with pytest.raises(ValueError):
            swapped()
    assert np.isfinite(theory.hertz_stiffness(R, r, E, nu))
