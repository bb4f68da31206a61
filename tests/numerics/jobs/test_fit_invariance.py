"""The fits change with the data's units and order only as they should (issue 24, items 2 and 5).

A change of units multiplies each column by a constant: forces by c_F, displacements by c_d,
speeds by c_L/c_t, masses by c_m.  The laws then hold with K of F = K delta^n multiplied by
c_F c_d^(-n) (K_c of Eq. 1 by c_F c_d^(-3/2), K_b by c_F/c_d), n unchanged, and with m_eff/m0 of
Eq. (8) unchanged; the order of the samples, and of the columns in a file, changes nothing.
The fits must follow exactly, their covariance carried by the Jacobian of the change (K's
factor c_d^(-n) depends on n, so K's standard error mixes with n's).  Before the least squares
were solved in scaled units (:func:`ringchain.numerics.jobs.fit.minimize`), forces in uN stopped
them early (n = 1.0883 +- 0.0036 where the same data in N give 1.0707).

One change is not a symmetry: the speed fit with n free holds K fixed in N/m^n, a unit that
depends on n, so a change of length units changes the constraint; there only time and mass
units are changed.

Tolerance of the values: the least squares stop within ftol = 1e-8 of the least sum of squares,
which leaves each parameter within sqrt(1e-8 dof) ~ 7e-4 standard errors of its minimum (dof
about 40 here); 0.01 standard errors is that with a margin of 14.  The standard errors
themselves come from the Jacobian at those two points: 1e-3 relative.
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain.numerics import fit_speed_amplitude, fit_static, read_static
from ringchain.theory import Ring, series_displacement, solitary_wave_speed

RING = Ring.from_aspect_ratio(9.0)
K_LAW, N_LAW = 4.9e6, 1.11  # N/m^n: about Table I's law
SAMPLES = 40
VALUES, ERRORS = 0.01, 1e-3  # in standard errors, and relative (module notes)


def static_data(model, seed):
    """(displacement m, force N) of a quasi-static test: the power law or the series law of the R/r = 9 ring,
    1-60 N with 0.3 N of noise."""
    rng = np.random.default_rng(seed)
    F = np.linspace(1.0, 60.0, SAMPLES)
    if model == "power-law":
        delta = (F / K_LAW) ** (1.0 / N_LAW)
    else:
        delta = series_displacement(F, K_c=RING.K_c, K_b=RING.K_b)
    return delta, F + 0.3 * rng.standard_normal(SAMPLES)


def in_new_units(fit, c_F, c_d):
    """(values, covariance) of a static fit in units that multiply forces by c_F and displacements by c_d: the values
    mapped, the covariance carried by the Jacobian of the map."""
    names, values = fit.names, dict(fit.values)
    sd = np.array([fit.stderr[name] for name in names])
    covariance = fit.correlation * np.outer(sd, sd)
    jacobian = np.eye(len(names))
    factors = {"K_c": c_F * c_d**-1.5, "K_b": c_F / c_d, "delta0": c_d}
    if "K" in names:
        factors["K"] = c_F * c_d ** -values["n"]
        jacobian[names.index("K"), names.index("n")] = -values["K"] * factors["K"] * math.log(c_d)  # dK'/dn
    for name, factor in factors.items():
        if name in names:
            jacobian[names.index(name), names.index(name)] = factor
            values[name] *= factor
    return values, jacobian @ covariance @ jacobian.T


@settings(max_examples=30, deadline=None, derandomize=True)
@given(
    force_decades=st.floats(-9.0, 9.0),
    displacement_decades=st.floats(-6.0, 6.0),
    model=st.sampled_from(["power-law", "series"]),
    offset=st.booleans(),
    seed=st.integers(0, 2**16),
    order=st.permutations(range(SAMPLES)),
)
def test_the_static_fit_follows_the_units_and_ignores_the_order(
    force_decades, displacement_decades, model, offset, seed, order
):
    delta, F = static_data(model, seed)
    c_F, c_d = 10.0**force_decades, 10.0**displacement_decades
    base = fit_static(delta, F, model, offset=offset)
    moved = fit_static(delta[order] * c_d, F[order] * c_F, model, offset=offset)
    values, covariance = in_new_units(base, c_F, c_d)
    sd = np.sqrt(np.diag(covariance))
    for i, name in enumerate(base.names):
        assert moved.values[name] == pytest.approx(values[name], abs=VALUES * moved.stderr[name]), name
        assert moved.stderr[name] == pytest.approx(sd[i], rel=ERRORS), name
    np.testing.assert_allclose(moved.correlation, covariance / np.outer(sd, sd), atol=ERRORS)
    assert moved.chisqr == pytest.approx(base.chisqr * c_F**2, rel=1e-6)  # ftol = 1e-8 of it, with a margin
    # AIC = N ln(chisqr/N) + 2k shifts by N ln(c_F^2) and compares the two laws the same in any units.
    assert moved.aic - base.aic == pytest.approx(SAMPLES * math.log(c_F**2), abs=1e-5)


@settings(max_examples=10, deadline=None, derandomize=True)
@given(columns=st.permutations(["displacement_m", "force_N", "temperature_C"]), seed=st.integers(0, 2**16))
def test_the_order_of_the_columns_in_a_static_file_changes_nothing(tmp_path_factory, columns, seed):
    delta, F = static_data("power-law", seed)
    values = {"displacement_m": delta, "force_N": F, "temperature_C": np.full(SAMPLES, 21.0)}
    path = tmp_path_factory.mktemp("static") / "test.csv"
    path.write_text(",".join(columns) + "\n" + "".join(
        ",".join(repr(float(values[c][i])) for c in columns) + "\n" for i in range(SAMPLES)))  # fmt: skip
    read_delta, read_F = read_static(path)
    np.testing.assert_array_equal(read_delta, delta)  # 17 digits: exact
    np.testing.assert_array_equal(read_F, F)
    assert fit_static(read_delta, read_F).values == fit_static(delta, F).values


@settings(max_examples=30, deadline=None, derandomize=True)
@given(
    time_decades=st.floats(-4.0, 4.0),
    length_decades=st.floats(-4.0, 4.0),
    mass_decades=st.floats(-4.0, 4.0),
    free_n=st.booleans(),
    seed=st.integers(0, 2**16),
    order=st.permutations(range(15)),
)
def test_the_speed_fit_follows_the_units_and_ignores_the_order(
    time_decades, length_decades, mass_decades, free_n, seed, order
):
    # Eq. (8) in new units: V -> V c_L/c_t, F_m -> F_m c_m c_L/c_t^2, K -> K c_m c_L^(1-n)/c_t^2, a -> a c_L,
    # m0 -> m0 c_m; m_eff/m0 and n are numbers, and stay.
    K, n = RING.power_law()
    F = np.geomspace(2.0, 150.0, 15)
    rng = np.random.default_rng(seed)
    V = solitary_wave_speed(F, K=K, n=n, m=0.37 * RING.mass, a=RING.spacing) * (1 + 0.01 * rng.standard_normal(15))
    c_t, c_m = 10.0**time_decades, 10.0**mass_decades
    c_L = 1.0 if free_n else 10.0**length_decades  # K in N/m^n: with n free, not a symmetry (module notes)
    chain = {"K": K, "n": n, "a": RING.spacing, "m0": RING.mass}
    base = fit_speed_amplitude(F, V, **chain, free_n=free_n)
    moved = fit_speed_amplitude((F * c_m * c_L / c_t**2)[order], (V * c_L / c_t)[order], K=K * c_m * c_L ** (1 - n)
                                / c_t**2, n=n, a=RING.spacing * c_L, m0=RING.mass * c_m, free_n=free_n)  # fmt: skip
    for name in base.names:
        assert moved.values[name] == pytest.approx(base.values[name], abs=VALUES * base.stderr[name]), name
        assert moved.stderr[name] == pytest.approx(base.stderr[name], rel=ERRORS), name
    assert moved.chisqr == pytest.approx(base.chisqr * (c_L / c_t) ** 2, rel=1e-6)  # as for the static fit
