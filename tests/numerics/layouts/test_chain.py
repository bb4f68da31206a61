"""Building chains: parameters, Ring and Table I, static equilibrium under gravity."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from ringchain.numerics import Chain, initial_state, paper_chain
from ringchain.theory import Ring, fit_power_law, paper_data

G = 9.81


def test_power_law_parameters_and_layout():
    chain = Chain.power_law(5, K=2e6, n=1.2, m=0.01, a=0.04)
    assert chain.m_gravity == chain.m  # default: gravity acts on the inertial mass
    assert chain.n_sites == 5 and chain.network().n_links == 5  # 4 contacts + the support
    assert chain.contact_links.tolist() == [0, 1, 2, 3] and chain.support_link == 4
    assert Chain.power_law(5, K=2e6, n=1.2, m=0.01, a=0.04, support="free").network().n_links == 4


def test_dual_spring_layout_pairs_contact_and_bending_as_the_paper():
    chain = Chain.dual_spring(4, K_c=7.5e9, K_b=3.3e6, m=0.008, a=0.04)
    lat = chain.network()
    # Bond 2j is ring j's body (bending), bond 2j+1 the contact of rings j and j+1, the last
    # one the support; each half ring weighs m/2.
    kinds = {type(law).__name__: index.tolist() for law, index in lat.groups}
    assert kinds == {"LinearSpring": [0, 2, 4, 6], "PowerLaw": [1, 3, 5, 7]}
    assert np.all(lat.mass == 0.004)
    assert chain.ring_sites(2).tolist() == [4, 5]


@pytest.mark.parametrize(
    ("kwargs", "error", "message"),
    [
        (dict(n_rings=1), ValueError, "n_rings must be at least 2"),
        (dict(n_rings=2.5), ValueError, "n_rings must be an integer, got 2.5"),
        (dict(n_rings=float("inf")), ValueError, "n_rings must be an integer, got inf"),  # was an OverflowError
        (dict(n_rings="5"), ValueError, "n_rings must be an integer, got '5'"),
        (dict(K=0.0), ValueError, "K must be positive"),
        (dict(n=0.5), ValueError, "n must lie in"),
        (dict(m=-1.0), ValueError, "m must be positive"),
        (dict(gamma=-1.0), ValueError, "gamma must be non-negative"),
        (dict(m_gravity=0.0), ValueError, "m_gravity must be positive"),
        (dict(support="hook"), ValueError, "support must be one of"),
    ],
)
def test_power_law_validates(kwargs, error, message):
    args = dict(n_rings=5, K=2e6, n=1.2, m=0.01, a=0.04) | kwargs
    with pytest.raises(error, match=message):
        Chain.power_law(**args)


def test_models_keep_their_own_parameters():
    with pytest.raises(ValueError, match="needs the bending stiffness"):
        Chain("dual-spring", 4, 1e9, 1.5, 0.01, 0.04)
    with pytest.raises(ValueError, match="belong to the dual-spring model"):
        Chain("power-law", 4, 1e9, 1.5, 0.01, 0.04, K_b=1e6)
    # The dual-spring contact is Hertz contact (Eq. 1): n = 2.7 used to be accepted.
    with pytest.raises(ValueError, match=r"Hertz contact, n = 3/2 \(Eq. 1\); got n = 2.7"):
        Chain("dual-spring", 4, 1e9, 2.7, 0.01, 0.04, K_b=1e6)


def test_flags_and_ring_indices_are_checked():
    chain = Chain.power_law(5, K=2e6, n=1.2, m=0.01, a=0.04)
    with pytest.raises(ValueError, match="first_ring_hanging must be True or False, got 'no'"):
        chain.static_extension(first_ring_hanging="no")  # a non-empty string used to mean True
    with pytest.raises(ValueError, match=r"ring indices must be integers in 0..4, got \[7\]"):
        chain.ring_sites([7])
    with pytest.raises(ValueError, match="ring indices must be integers"):
        chain.ring_sites(1.5)


def test_from_ring_uses_the_theory():
    ring = Ring.from_aspect_ratio(9.0)
    dual = Chain.from_ring(ring, 20, m_eff_ratio=0.37)
    assert (dual.K_c, dual.K_b, dual.n) == (ring.K_c, ring.K_b, 1.5)
    assert dual.m == pytest.approx(0.37 * ring.mass, rel=1e-15) and dual.m_gravity == ring.mass
    assert dual.a == ring.spacing
    power = Chain.from_ring(ring, 20, "power-law")
    assert (power.K, power.n) == ring.power_law()
    measured = Chain.from_ring(ring, 20, "power-law", K=4.9e6, n=1.11)
    assert (measured.K, measured.n) == (4.9e6, 1.11)


def test_from_ring_refuses_rings_that_cannot_form_a_chain():
    with pytest.raises(ValueError, match="cannot form a chain"):
        Chain.from_ring(Ring.from_aspect_ratio(2.5), 10)


def test_from_ring_checks_its_options():
    ring = Ring.from_aspect_ratio(9.0)
    with pytest.raises(ValueError, match="give both K and n"):
        Chain.from_ring(ring, 10, "power-law", K=1e6)
    with pytest.raises(ValueError, match="use gamma_c and gamma_b"):
        Chain.from_ring(ring, 10, "dual-spring", gamma=1.0)
    with pytest.raises(ValueError, match="m_eff_ratio must lie in"):
        Chain.from_ring(ring, 10, m_eff_ratio=1.5)
    with pytest.raises(TypeError, match=r"must be a ringchain\.theory\.Ring"):
        Chain.from_ring("ring", 10)


def test_from_paper_is_table_i():
    chain = paper_chain("power-law")
    K_mm, n, ratio = paper_data.TABLE_I[9.0]
    assert chain.n_rings == 20 and chain.n == n
    assert chain.K == pytest.approx(K_mm * 1000.0**n, rel=1e-14)  # N/mm^n -> N/m^n by hand
    ring = Ring.from_aspect_ratio(9.0, r=2.5e-3)
    assert chain.m == pytest.approx(ratio * ring.mass, rel=1e-15)
    assert paper_chain("dual-spring").K_b == ring.K_b  # the paper's own choice (Sec. III.B): theory
    with pytest.raises(ValueError, match="Table I has aspect ratios"):
        paper_chain("power-law", aspect_ratio=7.0)
    with pytest.raises(ValueError, match="stiffness must be one of"):
        paper_chain("power-law", stiffness="measured")


@pytest.mark.parametrize("aspect_ratio", sorted(paper_data.TABLE_I))
def test_from_paper_stiffness_sources(aspect_ratio):
    K_mm, n, _ = paper_data.TABLE_I[aspect_ratio]
    ring = Ring.from_aspect_ratio(aspect_ratio, r=2.5e-3)
    # "theory": the ring's springs (Eqs. 1-2) and the power law fitted to them (Eq. 4).
    dual = paper_chain("dual-spring", aspect_ratio, stiffness="theory")
    assert (dual.K_c, dual.K_b) == (ring.K_c, ring.K_b)
    power = paper_chain("power-law", aspect_ratio, stiffness="theory")
    assert (power.K, power.n) == ring.power_law()
    # "table": the dual-spring springs reduce to Table I's power law over 1-100 N (Eq. 4, fitted
    # by the theory's own fit_power_law): K by hand from N/mm^n, n as printed.
    dual = paper_chain("dual-spring", aspect_ratio, stiffness="table")
    K, n_fit = fit_power_law(K_c=dual.K_c, K_b=dual.K_b)
    assert float(K) == pytest.approx(K_mm * 1000.0**n, rel=1e-9)  # root finding to 1e-13 in ln F*
    assert float(n_fit) == pytest.approx(n, rel=1e-9)
    assert dual.n == 1.5 and dual.m == paper_chain("power-law", aspect_ratio).m


@pytest.mark.parametrize("model", ["power-law", "dual-spring"])
def test_hanging_chain_is_in_static_equilibrium(model):
    chain = paper_chain(model)
    x, u = initial_state(chain, gravity=True, g=G)
    lat = chain.network()
    forces = lat.forces(lat.extension(x[0]))
    # Contact i carries the weight of rings 0..i: (i + 1) m0 g; the support all 20 rings.
    contact = forces[chain.contact_links]
    np.testing.assert_allclose(contact, (np.arange(19) + 1) * chain.m_gravity * G, rtol=1e-12)
    assert forces[chain.support_link] == pytest.approx(20 * chain.m_gravity * G, rel=1e-12)
    # ... so nothing accelerates: residual relative to g, rounding of x ~ 1e-16 relative.
    assert np.abs(lat.accelerations(x[0], u[0], g=G)).max() < 1e-6 * G
    assert np.all(u == 0.0)


def test_dual_spring_ring_body_carries_half_its_own_weight_more():
    chain = paper_chain("dual-spring")
    x, _ = initial_state(chain, gravity=True, g=G)
    bending = chain.network().forces(chain.network().extension(x[0]))[chain.bending_links]
    # The body of ring j carries the rings below and its own lower half: (j + 1/2) m0 g.
    np.testing.assert_allclose(bending, (np.arange(20) + 0.5) * chain.m_gravity * G, rtol=1e-12)


@pytest.mark.parametrize("model", ["power-law", "dual-spring"])
def test_drop_starts_with_the_slack_just_taken_up(model):
    chain = paper_chain(model)
    h = 0.05
    x, u = initial_state(chain, drop_height=h, g=G)
    lat = chain.network()
    e = lat.extension(x[0])
    k = chain.sites_per_ring
    # Ring 0 falls freely: unloaded (its bonds at zero extension), moving at sqrt(2 g h) away from the chain.
    assert np.all(e[:k] == 0.0)
    np.testing.assert_allclose(u[0, :k], -np.sqrt(2 * G * h), rtol=1e-15)
    assert np.all(u[0, k:] == 0.0)
    # The rest hangs without ring 0's weight: contact i (i >= 1) carries i rings.
    contact = lat.forces(e)[chain.contact_links]
    np.testing.assert_allclose(contact[1:], np.arange(1, 19) * chain.m_gravity * G, rtol=1e-12)


def test_a_free_chain_has_no_hanging_equilibrium():
    chain = Chain.power_law(5, K=2e6, n=1.2, m=0.01, a=0.04, support="free")
    with pytest.raises(ValueError, match="fixed support"):
        initial_state(chain, impact_velocity=1.0, gravity=True)
    x, u = initial_state(chain, impact_velocity=1.0, gravity=False)
    assert np.all(x == 0.0) and u[0].tolist() == [-1.0, 0, 0, 0, 0]


ANY_NUMBER = st.one_of(st.floats(allow_nan=True, allow_infinity=True), st.integers(-10, 10**6), st.booleans())


@settings(max_examples=200, deadline=None)
@given(n_rings=ANY_NUMBER, K=ANY_NUMBER, n=ANY_NUMBER, m=ANY_NUMBER, a=ANY_NUMBER, gamma=ANY_NUMBER)
def test_any_parameters_give_a_chain_or_a_value_error(n_rings, K, n, m, a, gamma):
    try:
        chain = Chain.power_law(n_rings, K=K, n=n, m=m, a=a, gamma=gamma)
    except ValueError as exc:
        assert str(exc)  # with its reason
        return
    assert chain.n_rings >= 2 and all(np.isfinite([chain.K, chain.n, chain.m, chain.a, chain.gamma]))
