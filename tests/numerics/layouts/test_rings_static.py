"""The static state of rigid rings under gravity (:meth:`Rings.equilibrium`): residuals and the balance of weights."""

import numpy as np
import pytest
from ringchain.numerics import Rings
from ringchain.theory import STANDARD_GRAVITY, Ring

RING = Ring.from_aspect_ratio(9.0)


def assert_static(rest, tol):
    """Residuals of ``rest`` within ``tol`` m g (torques m g R), and its fixed rings carrying the free ones' weight."""
    _, forces, torques = rest.potential(rest.centres, rest.orientations)
    weight = RING.mass * STANDARD_GRAVITY
    free = ~rest.fixed
    # The solver's own bound, checked here from a search of every contact from scratch.
    assert np.abs(forces[free]).max() <= tol * weight
    assert np.abs(torques[free]).max() <= tol * weight * RING.R
    # Invariant (independent of the solver): the contacts push the fixed rings down by the weight of the free rings
    # (their own weight is not a contact force), to the residual force on each free ring, tol m g each.
    np.testing.assert_allclose(-forces[rest.fixed, 2].sum(), free.sum() * weight, atol=free.sum() * tol * weight)


@pytest.mark.parametrize("law", ["hertz", "power-law"])
def test_the_anchor_carries_the_weight_of_the_hanging_chain(law):
    tol = 1e-9
    assert_static(Rings.chain(6, RING, law=law).equilibrium(force_tol=tol), tol)


def test_a_small_sheet_of_chain_mail_hangs_from_its_top_row():
    sheet = Rings.mail(2, 3, RING)  # three free rings, each hung on two of the fixed row (one at the edges)
    tol = 1e-8
    rest = sheet.equilibrium(force_tol=tol)
    assert_static(rest, tol)
    # The rings hang: every free ring is lower than it was built (they rest on the row above, not on the layout).
    free = ~sheet.fixed
    assert np.all(rest.centres[free, 2] < sheet.centres[free, 2])


def test_equilibrium_names_a_bad_tolerance():
    with pytest.raises(ValueError, match="force_tol"):
        Rings.chain(3, RING).equilibrium(force_tol=-1.0)


@pytest.mark.parametrize("build", [lambda: Rings.chain(6, RING), lambda: Rings.mail(2, 3, RING)], ids=["chain", "mail"])
def test_the_first_order_phase_alone_reaches_the_static_state(build, monkeypatch):
    from ringchain.numerics.layouts import rings_static

    # The first phase (L-BFGS on the energy) handing over only at the tolerance itself: Newton's method runs only
    # if it stops short, so the phases must all be descents and the state found theirs.
    monkeypatch.setattr(rings_static, "HANDOVER", 0.0)
    network, tol = build(), 1e-8
    centres, orientations, phases = rings_static.static_state(network, force_tol=tol)
    assert [phase["phase"] for phase in phases] == ["descent"] * len(rings_static.SOFTENING)
    assert phases[-1]["residual"] <= tol
    # Independent of the solver: a search of every contact from scratch, and the weight carried by the fixed rings.
    assert_static(network.moved(centres, orientations), tol)


def test_the_phases_are_recorded():
    from ringchain.numerics.layouts.rings_static import static_state

    chain, tol = Rings.chain(3, RING), 1e-8
    centres, orientations, phases = static_state(chain, force_tol=tol)
    assert phases[0]["phase"] == "descent" and phases[0]["softening"] == 1e-3
    for phase in phases:
        assert phase["evaluations"] >= phase["iterations"] >= 0 and phase["wall"] >= 0.0
        assert phase["memory"] is None  # tracemalloc is not tracing
    assert phases[-1]["softening"] == 1.0 and phases[-1]["residual"] <= tol
    assert_static(chain.moved(centres, orientations), tol)
