"""The series law for a tabulated contact curve (theory/series.py): series_extension, fit_power_law_to_curve."""

import numpy as np
import pytest
import sympy as sp
from ringchain.theory import (
    fit_power_law,
    fit_power_law_to_curve,
    series,
    series_displacement,
    series_extension,
)


def test_series_extension_is_eq_3_with_any_contact():
    s = series.symbols()
    expr = series.series_extension_expr()
    assert sp.simplify(expr - (s["delta_c"] + s["F"] / s["K_b"])) == 0
    # With the Hertz contact extension it is the series law of Eq. (3).
    hertz = expr.subs(s["delta_c"], series.contact_extension())
    assert sp.simplify(hertz - series.total_extension()) == 0


def test_series_extension_numbers_and_errors():
    F = np.array([1.0, 10.0])
    K_c, K_b = 7.5e9, 2.5e6
    assert np.allclose(
        series_extension(F, delta_c=(F / K_c) ** (2 / 3), K_b=K_b), series_displacement(F, K_c=K_c, K_b=K_b), rtol=1e-14
    )
    with pytest.raises(ValueError, match="K_b"):
        series_extension(1.0, delta_c=1e-6, K_b=-1.0)


def test_fit_to_a_sampled_series_law_matches_the_continuous_fit():
    K_c, K_b = 7.5e9, 2.5e6
    F = np.geomspace(1.0, 100.0, 200)
    K, n = fit_power_law_to_curve(F, series_displacement(F, K_c=K_c, K_b=K_b))
    K_ref, n_ref = fit_power_law(K_c=K_c, K_b=K_b)
    # Linear interpolation of ln delta in ln F with 200 points per two decades: error ~ (h^2/8) |d2| ~ 1e-6.
    assert n == pytest.approx(float(n_ref), rel=1e-5)
    assert K == pytest.approx(float(K_ref), rel=1e-4)


def test_fit_with_fixed_exponent():
    F = np.geomspace(0.5, 200.0, 7)
    K, n = fit_power_law_to_curve(F, (F / 4.0) ** (1 / 1.5), n=1.5)
    assert (K, n) == (pytest.approx(4.0, rel=1e-12), 1.5)


def test_fit_window_must_lie_within_the_curve():
    F = np.geomspace(1.0, 50.0, 5)
    with pytest.raises(ValueError, match="within the curve"):
        fit_power_law_to_curve(F, F, 1.0, 100.0)
    with pytest.raises(ValueError, match="strictly increasing"):
        fit_power_law_to_curve(F[::-1], F)
