"""Thornton's elastic-perfectly plastic contact (theory/plastic.py): the derivation against Thornton's (1997)
closed forms, the force law against an integrated collision, and the ring's bending spring in series."""

import numpy as np
import pytest
import sympy as sp
from ringchain.theory import (
    Ring,
    bending_stiffness,
    contact_ellipse,
    contact_modulus,
    equivalent_radius,
    first_yield,
    hertz_stiffness,
    plastic,
    plastic_stiffness,
    restitution_coefficient,
    thornton_energy,
    thornton_loading_force,
    thornton_residual_indentation,
    thornton_unloading_force,
    yield_force,
    yield_velocity,
)
from scipy.integrate import solve_ivp
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

S = plastic.symbols()
delta, R_e, Es, p_y, K_c, delta_y, x, x_m, v = (
    S[k] for k in ("delta", "R_e", "Es", "p_y", "K_c", "delta_y", "x", "x_m", "v")
)
R, r, E, NU = 22.5e-3, 2.5e-3, 193e9, 0.29  # the paper's ring, AISI 304
RING = Ring(R, r)
M0 = RING.mass
DROP = np.sqrt(2 * 9.80665 * 0.05)  # a 5 cm drop, m/s


def thornton_e(ratio):
    """Thornton (1997), Eq. (23), as printed: e(V_y/V_i)."""
    q = np.asarray(ratio, dtype=float)
    return np.sqrt(6 * np.sqrt(3) / 5) * np.sqrt(1 - q**2 / 6) * (q / (q + 2 * np.sqrt(6 / 5 - q**2 / 5))) ** 0.25


# --- symbolic ----------------------------------------------------------------------------------------------


def test_hertz_sphere():
    P, peak, radius = plastic.hertz_sphere()
    assert sp.simplify(P - sp.Rational(4, 3) * Es * sp.sqrt(R_e) * delta ** sp.Rational(3, 2)) == 0
    assert sp.simplify(peak - 2 * Es * radius / (sp.pi * R_e)) == 0  # Johnson Eq. (4.25): p0 = 2 E* a/(pi R)
    assert sp.simplify(radius**2 - R_e * delta) == 0


def test_truncated_force_is_thorntons():
    F, yield_point = plastic.truncated_force()
    assert sp.simplify(yield_point - sp.pi**2 * p_y**2 * R_e / (4 * Es**2)) == 0
    F_y = sp.pi**3 * R_e**2 * p_y**3 / (6 * Es**2)  # the closed form with p0 = p_y
    # Thornton Eq. (14): F = F_y + pi p_y R (delta - delta_y)
    assert sp.simplify(F - (F_y + sp.pi * p_y * R_e * (delta - yield_point))) == 0
    hertz, _, _ = plastic.hertz_sphere()
    assert sp.simplify(hertz.subs(delta, yield_point) - F_y) == 0  # continuous at the yield point
    assert sp.simplify(sp.diff(hertz, delta).subs(delta, yield_point) - sp.diff(F, delta)) == 0  # and tangent


def test_loading_force_in_contact_constants():
    F, slope = plastic.loading_force()
    assert sp.simplify(F - K_c * delta_y ** sp.Rational(3, 2) * (3 * x - 1) / 2) == 0
    assert sp.simplify(slope - sp.Rational(3, 2) * K_c * sp.sqrt(delta_y)) == 0


def test_unloading_curve():
    F, delta_p = plastic.unloading_force()
    # delta_m - delta_p = a_m^2/R_p = delta_y (3 x_m - 1)/(2 sqrt(x_m)) (Thornton Eqs. (18)-(19))
    assert sp.simplify(x_m * delta_y - delta_p - delta_y * (3 * x_m - 1) / (2 * sp.sqrt(x_m))) == 0
    assert sp.simplify(delta_p.subs(x_m, 1)) == 0
    hertz = K_c * delta ** sp.Rational(3, 2)
    assert sp.simplify(sp.powdenest(F.subs(x_m, 1), force=True) - hertz) == 0  # x_m = 1: the Hertz curve
    F_load, _ = plastic.loading_force()
    top = sp.powdenest(F.subs(delta, x_m * delta_y), force=True)
    assert sp.simplify(top - F_load.subs(x, x_m)) == 0


def test_restitution_closed_form_is_thorntons():
    V_y, largest, e = plastic.impact()
    m = S["m"]
    assert sp.simplify(V_y**2 - sp.Rational(4, 5) * K_c * delta_y ** sp.Rational(5, 2) / m) == 0
    e_num = sp.lambdify(v, e)
    ratios = np.array([1.0, 1.5, 2.0, 10.0, 100.0, 1e4])
    np.testing.assert_allclose(e_num(ratios), thornton_e(1 / ratios), rtol=1e-13)  # the same function
    assert sp.simplify(largest.subs(v, 1) - 1) == 0


# --- the public numbers ----------------------------------------------------------------------------------


@pytest.mark.parametrize("ratio", [2.0, 10.0, 100.0])
def test_restitution_coefficient_against_thornton(ratio):
    m = M0 / 2
    V_y = float(yield_velocity(R, r, E, NU, Y=215e6, m=m))
    e = float(restitution_coefficient(ratio * V_y, R, r, E, NU, Y=215e6, m=m))
    # The issue asks for 0.5 %; derivation and Thornton's printed formula agree to rounding.
    assert e == pytest.approx(float(thornton_e(1 / ratio)), rel=1e-12)


def test_restitution_is_one_below_the_yield_speed_and_continuous():
    m = M0 / 2
    V_y = float(yield_velocity(R, r, E, NU, Y=215e6, m=m))
    e = restitution_coefficient(V_y * np.array([0.0, 0.5, 1.0, 1.0 + 1e-9, 2.0]), R, r, E, NU, Y=215e6, m=m)
    assert np.all(e[:3] == 1.0)
    assert e[3] == pytest.approx(1.0, abs=1e-8)  # de/dv is finite at v = V_y
    assert e[4] < 1.0


def test_yield_velocity_is_the_hertz_energy():
    m = M0 / 2
    y = first_yield(R, r, E, NU, Y=215e6)
    V_y = float(yield_velocity(R, r, E, NU, Y=215e6, m=m))
    assert m * V_y**2 / 2 == pytest.approx(0.4 * float(y.force) * float(y.indentation), rel=1e-12)


def test_paper_ring_numbers():
    m = M0 / 2  # two free rings of the paper's chain
    annealed = float(restitution_coefficient(DROP, R, r, E, NU, Y=215e6, m=m))
    cold = float(restitution_coefficient(DROP, R, r, E, NU, Y=1e9, m=m))
    assert annealed == pytest.approx(0.21, abs=0.005)  # the "about 0.21 at a 5 cm drop"
    assert annealed < cold < 1.0
    assert float(yield_velocity(R, r, E, NU, Y=215e6, m=m)) < 1e-3  # m/s: any drop yields the annealed contact


# --- the force law ---------------------------------------------------------------------------------------------


def test_force_law_shape():
    K, dy = 2.0, 1e-6
    deltas = np.linspace(-dy, 5 * dy, 601)
    load = thornton_loading_force(deltas, K_c=K, delta_y=dy)
    assert np.all(load[deltas <= 0] == 0)
    hertz = deltas <= dy
    np.testing.assert_allclose(load[hertz & (deltas > 0)], K * deltas[hertz & (deltas > 0)] ** 1.5, rtol=1e-14)
    slope = np.diff(load[~hertz]) / np.diff(deltas[~hertz])
    np.testing.assert_allclose(slope, 1.5 * K * np.sqrt(dy), rtol=1e-9)  # a straight line (rounding of diff)
    # Unloading from 4 delta_y: starts at the loading force, opens at delta_p, retraced on reloading.
    top = 4 * dy
    unload = thornton_unloading_force(deltas, delta_max=top, K_c=K, delta_y=dy)
    delta_p = float(thornton_residual_indentation(top, delta_y=dy))
    assert delta_p == pytest.approx(top - dy * 11 / 4, rel=1e-14)  # (3 x_m - 1)/(2 sqrt(x_m)) = 11/4 at x_m = 4
    assert np.all(unload[deltas <= delta_p] == 0)
    assert float(thornton_unloading_force(top, delta_max=top, K_c=K, delta_y=dy)) == pytest.approx(
        float(thornton_loading_force(top, K_c=K, delta_y=dy))
    )
    beyond = deltas >= top
    np.testing.assert_allclose(unload[beyond], load[beyond], rtol=1e-14)  # past the memory: the loading curve
    assert np.all(unload[(deltas > delta_p) & (deltas < top)] < load[(deltas > delta_p) & (deltas < top)])
    # Below the yield point nothing is remembered: the Hertz curve both ways.
    np.testing.assert_allclose(
        thornton_unloading_force(deltas, delta_max=0.5 * dy, K_c=K, delta_y=dy)[hertz], load[hertz], rtol=1e-14
    )
    assert float(thornton_residual_indentation(0.5 * dy, delta_y=dy)) == 0.0


def test_energies():
    K, dy = 3.0, 2e-6
    top = 7 * dy
    delta_p = float(thornton_residual_indentation(top, delta_y=dy))
    grid = np.linspace(delta_p, top, 2001)
    stored, dissipated = thornton_energy(grid, delta_max=top, K_c=K, delta_y=dy)
    force = thornton_unloading_force(grid, delta_max=top, K_c=K, delta_y=dy)
    # The force is the derivative of the stored energy (trapezoidal rule: error ~ h^2 F''/12 ~ 1e-7 relative).
    work = np.concatenate([[0.0], np.cumsum(0.5 * (force[1:] + force[:-1]) * np.diff(grid))])
    np.testing.assert_allclose(stored, work, rtol=1e-6, atol=1e-7 * stored[-1])
    assert np.all(dissipated == dissipated[0])  # the plastic work depends on the memory only
    # Along the loading curve stored + dissipated is the work of loading.
    load_grid = np.linspace(0.0, top, 4001)
    load = thornton_loading_force(load_grid, K_c=K, delta_y=dy)
    loading_work = np.sum(0.5 * (load[1:] + load[:-1]) * np.diff(load_grid))
    s_top, d_top = thornton_energy(top, delta_max=top, K_c=K, delta_y=dy)
    assert float(s_top + d_top) == pytest.approx(loading_work, rel=1e-6)  # trapezoid over the Hertz part's kink
    assert float(thornton_energy(0.5 * dy, delta_max=0.0, K_c=K, delta_y=dy)[1]) == 0.0
    assert float(thornton_energy(-dy, delta_max=top, K_c=K, delta_y=dy)[0]) == 0.0


# --- integrated collisions -------------------------------------------------------------------------------


def collide(V, m, contact_force, top_event=True):
    """Two rigid bodies of reduced mass m meeting at V: (e, largest approach, final state).

    ``contact_force(delta, delta_max)`` is the law; loading until the approach stops growing (the memory is
    then the largest approach), unloading until the contact opens (the force vanishes).
    """
    tight = dict(rtol=1e-11, atol=1e-22, method="DOP853")

    def loading(t, state):
        return [state[1], -contact_force(state[0], None) / m]

    def turn(t, state):
        return state[1]

    turn.terminal, turn.direction = True, -1
    scale = 1e-3 / max(V, 1e-9)
    first = solve_ivp(loading, (0, scale), [0.0, V], events=turn, **tight)
    assert first.status == 1
    top = first.y[0, -1]

    def unloading(t, state):
        return [state[1], -contact_force(state[0], top) / m]

    def opens(t, state):
        return contact_force(state[0], top) - 1e-12 * contact_force(top, top)

    opens.terminal, opens.direction = True, -1
    second = solve_ivp(unloading, (0, scale), [top, 0.0], events=opens, **tight)
    assert second.status == 1
    return -second.y[1, -1] / V, top


def contact_law(K, dy):
    def force(delta_, top):
        if top is None:
            return float(thornton_loading_force(delta_, K_c=K, delta_y=dy))
        return float(thornton_unloading_force(delta_, delta_max=top, K_c=K, delta_y=dy))

    return force


@pytest.mark.parametrize("ratio", [2.0, 10.0, 100.0])
def test_integrated_collision_gives_thorntons_restitution(ratio):
    m = M0 / 2
    K = float(hertz_stiffness(R, r, E, NU))
    dy = float(first_yield(R, r, E, NU, Y=215e6).indentation)
    V_y = float(yield_velocity(R, r, E, NU, Y=215e6, m=m))
    e, top = collide(ratio * V_y, m, contact_law(K, dy))
    # The issue asks for 1 %; the integration (rtol 1e-11, events located to ~1e-12) resolves e to ~1e-7.
    assert e == pytest.approx(float(restitution_coefficient(ratio * V_y, R, r, E, NU, Y=215e6, m=m)), rel=1e-6)
    stored, dissipated = thornton_energy(top, delta_max=top, K_c=K, delta_y=dy)
    assert float(stored + dissipated) == pytest.approx(m * (ratio * V_y) ** 2 / 2, rel=1e-7)  # energy at the top


def series_law(K, dy, K_b):
    """Contact and the ring's bending spring in series (massless junction): F from delta = delta_c(F) + F/K_b.

    The contact's memory is its own largest approach, reached with the largest force."""
    F_y = K * dy**1.5

    def contact_of_force(F, top_c):
        if top_c is None:  # the loading curve inverted
            return (F / K) ** (2 / 3) if F <= F_y else dy * (2 * F / F_y + 1) / 3
        F_m = float(thornton_loading_force(top_c, K_c=K, delta_y=dy))
        d_p = float(thornton_residual_indentation(top_c, delta_y=dy))
        return d_p + (top_c - d_p) * (F / F_m) ** (2 / 3)

    state = {}

    def force(delta_, top):
        if top is not None and "top_c" not in state:
            F_m = brentq(lambda F: contact_of_force(F, None) + F / K_b - top, 0.0, K_b * top, xtol=1e-16, rtol=1e-15)
            state["top_c"] = contact_of_force(F_m, None)
            state["F_m"] = F_m
        top_c = None if top is None else state["top_c"]
        hi = K_b * max(delta_, 0.0)
        if hi <= 0 or contact_of_force(0.0, top_c) + 0.0 >= delta_:
            return 0.0
        return brentq(lambda F: contact_of_force(F, top_c) + F / K_b - delta_, 0.0, hi, xtol=1e-18, rtol=1e-14)

    return force, state


def test_bending_spring_in_series_raises_the_restitution():
    """The e the chain sees: contact and bending in series (paper Eq. (3)) for two rings from a 5 cm drop.

    Why it differs: the bending spring stores F_m^2/(2 K_b) elastically and returns it, and it takes part of the
    approach, so the contact is driven less far into its plastic branch (whose slope pi p_y R_e is close to K_b).
    """
    m = M0 / 2
    K = float(hertz_stiffness(R, r, E, NU))
    K_b = float(bending_stiffness(R, r, E, NU))
    results = {}
    for Y in (215e6, 1e9):
        dy = float(first_yield(R, r, E, NU, Y=Y).indentation)
        alone = float(restitution_coefficient(DROP, R, r, E, NU, Y=Y, m=m))
        law, state = series_law(K, dy, K_b)
        e, _ = collide(DROP, m, law)
        # The energy account of the series contact predicts e: the contact reaches the force F_m with
        # m V^2/2 = W_load(contact) + F_m^2/(2 K_b), and returns W_unload(contact) + F_m^2/(2 K_b).
        F_m, top_c = state["F_m"], state["top_c"]
        stored, dissipated = (float(w) for w in thornton_energy(top_c, delta_max=top_c, K_c=K, delta_y=dy))
        spring = F_m**2 / (2 * K_b)
        assert stored + dissipated + spring == pytest.approx(m * DROP**2 / 2, rel=1e-7)  # integration accuracy
        assert e == pytest.approx(np.sqrt((stored + spring) / (m * DROP**2 / 2)), rel=1e-6)
        assert e > alone
        results[Y] = (alone, e)
    # The numbers of the report, to the 3 digits quoted: from a 5 cm drop (V/V_y = 1081 annealed, 23 cold-drawn)
    # e rises from 0.207 to 0.713 (annealed) and from 0.537 to 0.945 (cold-drawn) with the bending spring.
    assert results[215e6][0] == pytest.approx(0.207, abs=5e-4)
    assert results[215e6][1] == pytest.approx(0.713, abs=5e-4)
    assert results[1e9][0] == pytest.approx(0.537, abs=5e-4)
    assert results[1e9][1] == pytest.approx(0.945, abs=5e-4)
    # "The plastic slope is close to K_b": within 10 % for annealed 304, so the series slope is about half.
    assert float(plastic_stiffness(R, r, E, NU, Y=215e6)) == pytest.approx(K_b, rel=0.1)


# --- the equivalent sphere of the elliptical contact --------------------------------------------------------------


def test_equivalent_radius_at_90_degrees():
    assert float(equivalent_radius(R, r)) == pytest.approx(r * (R - r) / (R - 2 * r), rel=1e-14)  # App. A


@pytest.mark.parametrize(("angle_deg", "over_mean"), [(60.0, 1.0987), (45.0, 1.4158)])
def test_equivalent_sphere_is_thorntons_construction_on_the_ellipse(angle_deg, over_mean):
    """(iii) the truncated elliptical Hertz pressure has the sphere's plastic slope; (iv) the flat elliptical
    punch of the Hertz ellipse has the sphere's unloading stiffness (module docstring)."""
    angle = np.radians(angle_deg)
    A, B, m = (float(q) for q in contact_ellipse(R, r, angle))
    E_star = float(contact_modulus(E, NU))
    y = first_yield(R, r, E, NU, angle, Y=215e6)
    K_m, E_m = ellipk(m), ellipe(m)
    p0 = float(y.pressure)
    semi_a = p0 * np.sqrt(1 - m) * (K_m - E_m) / (m * A * E_star)  # Johnson Sec. 4.2: A = p0 b (K - E)/(E* a^2 m)
    semi_b = semi_a * np.sqrt(1 - m)
    dy = float(y.indentation)
    # (iii) F = pi a b (p_y - p_y^3/(3 p0(delta)^2)) with a b ~ delta and p0^2 ~ delta: slope pi p_y a b/delta.
    assert np.pi * p0 * semi_a * semi_b / dy == pytest.approx(float(plastic_stiffness(R, r, E, NU, angle, Y=215e6)))
    # (iv) flat elliptical punch (Johnson Sec. 3.6): stiffness pi E* a/K(m), at the contact of 5 delta_y.
    a5 = semi_a * np.sqrt(5)  # the Hertz semi-axes grow as sqrt(delta)
    R_e = float(equivalent_radius(R, r, angle))
    assert np.pi * E_star * a5 / K_m == pytest.approx(2 * E_star * np.sqrt(R_e * 5 * dy), rel=1e-9)
    # R_e against the geometric mean of the principal relative radii 1/(2A), 1/(2B) (the docstring's numbers).
    assert R_e * 2 * np.sqrt(A * B) == pytest.approx(over_mean, abs=1e-4)
    assert float(yield_force(R, r, E, NU, angle, Y=215e6)) == pytest.approx(2 / 3 * np.pi * semi_a * semi_b * p0)


# --- far from the paper's numbers: the law in forms that stay within double precision ---------------------------


def test_thornton_law_far_beyond_the_yield_point():
    """Each of these came out wrong when the law was evaluated in x_m = delta_m/delta_y (issue 24 extreme arguments)."""
    K, dy = 7.5e9, 7.5e-7
    # At delta_max = 1e40 delta_y the unloading curve's u = delta_m - delta_p was a difference of two equal
    # doubles: the force at delta_max, the loading force 1.5 K sqrt(dy) (delta - dy/3), came out as 0.
    top = 1e40 * dy
    load = 1.5 * K * np.sqrt(dy) * (top - dy / 3)
    assert float(thornton_unloading_force(top, delta_max=top, K_c=K, delta_y=dy)) == pytest.approx(load, rel=1e-14)
    assert float(thornton_loading_force(top, K_c=K, delta_y=dy)) == pytest.approx(load, rel=1e-14)
    # x_m^(3/2) overflowed (a refusal) for delta_max/delta_y beyond 1e205: delta_p = delta_m - 3/2 sqrt(dy delta_m).
    far = 1e300
    assert float(thornton_residual_indentation(far, delta_y=dy)) == pytest.approx(far - 1.5 * np.sqrt(dy * far))
    # delta_y^(3/2) and delta_y^(5/2) underflowed for a tiny delta_y (a zero force and a zero plastic work):
    # the force is 3/2 K sqrt(dy) delta and the work 3/4 K sqrt(dy) delta_m^2 to leading order.
    tiny = 1e-300
    assert float(thornton_loading_force(2e-6, K_c=K, delta_y=tiny)) == pytest.approx(1.5 * K * 1e-150 * 2e-6)
    stored, dissipated = thornton_energy(2e-6, delta_max=3e-6, K_c=K, delta_y=tiny)
    assert float(stored) == 0.0 and float(dissipated) == pytest.approx(0.75 * K * 1e-150 * 9e-12)
    # x_m^2 overflowed in the work of loading at delta = 1e150 m, which is 4.9e306 J.
    _, work = thornton_energy(1e150, delta_max=0.0, K_c=K, delta_y=dy)
    assert float(work) == pytest.approx(0.75 * K * np.sqrt(dy) * 1e300, rel=1e-12)


def test_impact_far_beyond_the_yield_speed_and_at_extreme_moduli():
    m = M0 / 2
    V_y = float(yield_velocity(R, r, E, NU, Y=215e6, m=m))
    # 6 v^2 - 1 overflowed for v = V/V_y beyond 1e154 (a refusal); e ~ sqrt(6/5) (2/3 sqrt(6/5) v)^(-1/4).
    e = float(restitution_coefficient(1e200 * V_y, R, r, E, NU, Y=215e6, m=m))
    assert e == pytest.approx(np.sqrt(1.2) * (2 / 3 * np.sqrt(1.2) * 1e200) ** -0.25, rel=1e-12)
    # A stiff material: F_y/K_c = 2e-427 underflowed on the way to delta_y = (F_y/K_c)^(2/3) = 3e-285 m, and V_y and
    # the plastic slope came out as 0.  V_y scales as 1/E^2 at a fixed nu; the plastic slope pi p_y R_e not at all.
    stiff = 1e150
    assert float(yield_velocity(R, r, stiff, NU, Y=215e6, m=m)) == pytest.approx(V_y * (E / stiff) ** 2, rel=1e-11)
    slope = float(plastic_stiffness(R, r, E, NU, Y=215e6))
    assert float(plastic_stiffness(R, r, stiff, NU, Y=215e6)) == pytest.approx(slope, rel=1e-11)
    # Where delta_y itself leaves the doubles the contact functions say so instead of answering 0 or refusing e.
    with pytest.raises(ValueError, match=r"approach at first yield, delta_y = 0\.0 m, lies below the normal range"):
        restitution_coefficient(DROP, R, r, 1e300, NU, Y=215e6, m=m)  # delta_y ~ (Y/E)^2: 4e-584 m
    # A yield strength in MPa read as Pa (issue 31, item 4) is refused, naming the unit.
    with pytest.raises(ValueError, match=r"Y = 215 Pa is below 1 MPa"):
        restitution_coefficient(DROP, R, r, E, NU, Y=215, m=m)


# --- inputs --------------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("call", "message"),
    [
        (lambda: thornton_loading_force(1e-6, K_c=-1.0, delta_y=1e-6), "K_c must be positive"),
        (lambda: thornton_loading_force(np.nan, K_c=1.0, delta_y=1e-6), "delta must be finite"),
        (
            lambda: thornton_unloading_force(1e-6, delta_max=-1e-6, K_c=1.0, delta_y=1e-6),
            "delta_max must be non-negative",
        ),
        (lambda: thornton_residual_indentation(1e-6, delta_y=0.0), "delta_y must be positive"),
        (lambda: thornton_energy([1.0, 2.0], delta_max=[1.0, 2.0, 3.0], K_c=1.0, delta_y=1.0), "cannot be broadcast"),
        (lambda: yield_velocity(R, r, E, NU, Y=215e6, m=0.0), "m must be positive"),
        (lambda: restitution_coefficient(-1.0, R, r, E, NU, Y=215e6, m=0.01), "v must be non-negative"),
        (lambda: plastic_stiffness(R, r, E, NU, Y=0.0), "Y must be positive"),
        (lambda: equivalent_radius(R, 0.6 * R), "R must exceed 2 r"),
    ],
)
def test_bad_input_is_refused(call, message):
    with pytest.raises(ValueError, match=message):
        call()
