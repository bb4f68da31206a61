"""Ring bending by Castigliano (paper Eq. 2): Roark's form, thin limit, term by term, numerics."""

import mpmath
import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain.theory import bending_stiffness, ring

S = ring.symbols()
W, R, r, E, nu, A, J, G, F = (S[k] for k in ("W", "R", "r", "E", "nu", "A", "J", "G", "F"))


def test_full_energy_gives_roarks_form():
    assert sp.simplify(ring.elongation() - ring.roark_elongation()) == 0


def test_roark_bracket_with_papers_k1_k2():
    # Paper Eq. (2): delta = W R^3/(E I) (pi k1/4 - 2 k2^2/pi), k1 = 1 - alpha + beta, k2 = 1 - alpha,
    # with Roark's alpha = I/(A R^2) and beta = F E I/(G A R^2) (here I -> J).
    alpha, beta = J / (A * R**2), F * E * J / (G * A * R**2)
    k1, k2 = 1 - alpha + beta, 1 - alpha
    expected = W * R**3 / (E * J) * (sp.pi * k1 / 4 - 2 * k2**2 / sp.pi)
    assert sp.simplify(ring.elongation() - expected) == 0


def test_thin_ring_limit():
    thin = ring.elongation(normal=False, coupling=False, shear=False)
    assert sp.simplify(thin - W * R**3 / (E * J) * (sp.pi / 4 - 2 / sp.pi)) == 0
    # The full result tends to the thin one as the section becomes rigid in shear and extension.
    full = ring.elongation()
    assert sp.simplify(sp.limit(sp.limit(full, A, sp.oo), G, sp.oo) - thin) == 0


def test_each_energy_term_contribution():
    alpha, beta = sp.symbols("alpha beta", positive=True)
    parts = ring.term_contributions()
    assert sp.simplify(parts["bending"] - (sp.pi / 4 - 2 / sp.pi)) == 0
    assert sp.simplify(parts["shear"] - sp.pi * beta / 4) == 0
    assert sp.simplify(parts["normal"] - sp.pi * alpha / 4) == 0
    assert sp.simplify(parts["coupling"] - (-sp.pi * alpha / 2 + 4 * alpha / sp.pi - 2 * alpha**2 / sp.pi)) == 0
    total = sum(parts.values())
    k1, k2 = 1 - alpha + beta, 1 - alpha
    assert sp.simplify(total - (sp.pi * k1 / 4 - 2 * k2**2 / sp.pi)) == 0


@pytest.mark.parametrize("aspect", [1.5, 3.1, 9.0])
def test_neutral_axis_integral_closed_form(aspect):
    integrand, y, (lo, hi) = ring.neutral_axis_integrand()
    values = {R: sp.Rational(str(aspect)), r: 1}
    f = sp.lambdify(y, integrand.subs(values), "mpmath")
    with mpmath.workdps(30):
        numeric = mpmath.quad(f, [lo.subs(values), hi.subs(values)])
        e_numeric = mpmath.mpf(str(aspect)) - mpmath.pi / numeric  # R - A / integral(dA/rho)
    section = ring.section_properties()
    assert abs(section["e"].subs(values).evalf(30) - sp.Float(e_numeric, 30)) < 1e-25  # quadrature at 30 digits


def test_thick_section_tends_to_thin():
    section = ring.section_properties()
    eps = sp.Symbol("epsilon", positive=True)
    J_series = sp.series((section["J"] / section["I"]).subs(r, eps * R), eps, 0, 2).removeO()
    assert sp.simplify(J_series - 1) == 0  # J = A e R = I (1 + O((r/R)^2))


def test_thin_numeric_equals_classical_value():
    R_, r_, E_ = 22.5e-3, 2.5e-3, 193e9
    second_moment = np.pi * r_**4 / 4
    expected = E_ * second_moment / R_**3 / (np.pi / 4 - 2 / np.pi)  # Roark Table 9.2 case 1 with k1 = k2 = 1
    assert np.isclose(bending_stiffness(R_, r_, E_, 0.29, thin=True), expected, rtol=1e-13, atol=0)


def _roark_thick_ring(R_, r_, E_, nu_):
    """Roark, Table 9.2 case 1 (ring pulled across a diameter), thick-ring form, typed here and
    evaluated by mpmath: delta = W R^3/(E J) (pi k1/4 - 2 k2^2/pi), k1 = 1 - alpha + beta,
    k2 = 1 - alpha, alpha = e/R, beta = 2 F (1 + nu) e/R with the shear form factor F = 10/9 of a
    solid circular section, J = A e R, and Winkler's offset of the neutral axis of a circle,
    e = R - R_n with R_n = (R + sqrt(R^2 - r^2))/2.  Returns K_b = W/delta."""
    with mpmath.workdps(30):
        R, r, E, nu = (mpmath.mpf(value) for value in (R_, r_, E_, nu_))
        e = R - (R + mpmath.sqrt(R**2 - r**2)) / 2
        J = mpmath.pi * r**2 * e * R
        alpha, beta = e / R, 2 * mpmath.mpf(10) / 9 * (1 + nu) * e / R
        k1, k2 = 1 - alpha + beta, 1 - alpha
        return float(E * J / (R**3 * (mpmath.pi * k1 / 4 - 2 * k2**2 / mpmath.pi)))


@pytest.mark.parametrize("aspect", [1.2, 3.1, 9.0, 30.0, 1e4])
def test_thick_numeric_against_roarks_table(aspect):
    R_, r_ = aspect * 2.5e-3, 2.5e-3
    # Double precision; the bracket subtracts nearly equal terms (pi k1/4 - 2 k2^2/pi ~ 0.15),
    # costing one digit: 1e-12.
    assert np.isclose(
        bending_stiffness(R_, r_, 193e9, 0.29), _roark_thick_ring(R_, r_, 193e9, 0.29), rtol=1e-12, atol=0
    )


def test_thin_flag_must_be_a_boolean():
    with pytest.raises(TypeError, match="thin must be True or False, got 'no'"):
        bending_stiffness(22.5e-3, 2.5e-3, 193e9, 0.29, thin="no")  # a truthy string, once taken for True
    assert bending_stiffness(22.5e-3, 2.5e-3, 193e9, 0.29, thin=np.bool_(True)) == bending_stiffness(
        22.5e-3, 2.5e-3, 193e9, 0.29, thin=True
    )


def test_broadcasting_error_names_the_arguments():
    with pytest.raises(ValueError, match=r"R \(shape \(3,\)\) and nu \(shape \(2,\)\)"):
        bending_stiffness([20e-3, 21e-3, 22e-3], 2.5e-3, 193e9, [0.2, 0.3])


def test_extreme_sizes_give_a_reason_not_nan():
    # R^2 overflows on the way: a ValueError that says so (before: NaN and a RuntimeWarning).
    with pytest.raises(ValueError, match="K_b is not representable"):
        bending_stiffness(1e300, 2.5e-3, 193e9, 0.29)


def test_thick_is_softer_and_approaches_thin():
    aspects = np.array([3.1, 5.0, 10.0, 100.0])
    R_ = aspects * 2.5e-3
    ratio = bending_stiffness(R_, 2.5e-3, 193e9, 0.29, thin=True) / bending_stiffness(R_, 2.5e-3, 193e9, 0.29)
    assert np.all(ratio > 1)
    assert np.all(np.diff(ratio) < 0)
    # alpha, beta ~ (r/R)^2: at R/r = 100 the two differ by O(1e-4) relative to a bracket of 0.15.
    assert ratio[-1] - 1 < 1e-3


@pytest.mark.parametrize(
    ("args", "message"),
    [
        ((2.5e-3, 2.5e-3, 193e9, 0.29), "r must be smaller than R"),
        ((20e-3, 0.0, 193e9, 0.29), "r must be positive"),
        ((20e-3, 2.5e-3, 193e9, -1.5), "nu must lie in"),
    ],
)
def test_bad_inputs(args, message):
    with pytest.raises(ValueError, match=message):
        bending_stiffness(*args)


@settings(max_examples=50, deadline=None)
@given(aspect=st.floats(1.05, 200.0), r_=st.floats(1e-4, 1e-2), nu_=st.floats(0.0, 0.49))
def test_positive(aspect, r_, nu_):
    for thin in (True, False):
        K = bending_stiffness(aspect * r_, r_, 193e9, nu_, thin=thin)
        assert np.isfinite(K) and K > 0


def test_stiffness_expression_thin_is_the_classical_closed_form():
    # Thin ring: delta = (pi/4 - 2/pi) W R^3/(E I) with I = pi r^4/4 (Roark, Table 9.2 case 1, k1 = k2 = 1).
    s = ring.symbols()
    R, r, E = s["R"], s["r"], s["E"]
    classical = sp.pi**2 * E * r**4 / (R**3 * (sp.pi**2 - 8))
    assert sp.simplify(ring.stiffness_expression(thin=True) - classical) == 0
    # The thick form keeps the Poisson ratio (through G) and tends to the thin one for a slender ring.
    thick = ring.stiffness_expression()
    assert s["nu"] in thick.free_symbols
    assert sp.simplify(sp.limit(thick / classical, R, sp.oo)) == 1
