"""Contacts that yield in the engine (issue 22): Thornton's law with memory in the compiled integrators, the
viscoelastic contact and the ring's loss factor, and the paper's chain with annealed contacts."""

import numpy as np
import pytest
from ringchain import theory
from ringchain.numerics import Chain, Network, simulate
from ringchain.numerics.engine import kernels
from ringchain.numerics.jobs.paper import paper_chain
from ringchain.numerics.laws import HuntCrossley, LinearSpring, Thornton, loss_factor_spring

R, r, E, NU, Y = 22.5e-3, 2.5e-3, 193e9, 0.29, 215e6  # the paper's ring, annealed AISI 304
M0 = 7900.0 * 2 * np.pi**2 * R * r**2  # kg, one ring
K_C = float(theory.hertz_stiffness(R, r, E, NU))
DELTA_Y = float(theory.first_yield(R, r, E, NU, Y=Y).indentation)
V_Y = float(theory.yield_velocity(R, r, E, NU, Y=Y, m=M0 / 2))


def largest_approach(ratio):
    """Thornton's x_m delta_y of a collision at V = ratio V_y (step 6 of ringchain.theory.plastic)."""
    return DELTA_Y * (1 + 2 * np.sqrt((6 * ratio**2 - 1) / 5)) / 3


def collide(law_links, masses, ratio, method="dopri5", struck=1, **options):
    """Two free rings meeting at V = ratio V_y: the first ``struck`` sites move at -V; returns (sim, V)."""
    V = ratio * V_Y
    net = Network(masses, law_links)
    u0 = np.zeros(len(masses))
    u0[:struck] = -V
    t_end = 12 * largest_approach(ratio) / V  # the approach and the rebound take a few delta_m/V
    sim = simulate(net, t_end, initial=(np.zeros(len(masses)), u0), gravity=False, n_samples=201, method=method,
                   **options)  # fmt: skip
    return sim, V


@pytest.mark.parametrize("ratio", [2.0, 10.0, 100.0])
def test_integrated_collision_gives_thorntons_restitution(ratio):
    sim, V = collide([(0, 1, Thornton(K_C, DELTA_Y))], [M0, M0], ratio)
    e = (sim.u[-1, 0] - sim.u[-1, 1]) / V  # the extension grew at V, it shrinks at e V
    expected = float(theory.restitution_coefficient(V, R, r, E, NU, Y=Y, m=M0 / 2))
    # The issue asks 1 %; the integration (rtol 3e-10) and the memory read from the cubic over a step (error
    # O(h^4)) do far better, 1e-6 leaves room for the contact's kink at reopening.
    assert e == pytest.approx(expected, rel=1e-6)
    # The memory is the true largest approach: a trial stage or a rejected step writing it would leave it at the
    # stage's overshoot; the memory read at the peak of the step is fourth order, 1e-8 relative here.
    assert sim.memory[-1, 0] == pytest.approx(largest_approach(ratio), rel=1e-8)
    # The plastic work is the energy lost, (1 - e^2) of the impact's m V^2/2 with m = M0/2.
    budget = sim.energy()
    assert budget.plastic[-1] == pytest.approx((1 - e**2) * 0.25 * M0 * V**2, rel=1e-6)  # integration, as above


def test_trial_stages_do_not_write_the_memory():
    """The compiled right-hand side reads the memory and never writes it; a stage beyond it is on the loading
    line, below it on the curve of the flattened tip."""
    net = Network([M0, M0], [(0, 1, Thornton(K_C, DELTA_Y))])
    packed = kernels.pack(net)
    memory = np.array([3 * DELTA_Y])
    for approach in (0.5, 2.5, 3.5, 10.0):  # below the residual approach, unloading, loading beyond the memory
        x = np.array([0.0, approach * DELTA_Y])
        a = kernels.accelerations(packed, x, g=0.0, memory=memory)
        assert memory[0] == 3 * DELTA_Y  # exact: never written
        expected = float(theory.thornton_unloading_force(x[1], delta_max=memory[0], K_c=K_C, delta_y=DELTA_Y))
        assert a[0] * M0 == pytest.approx(expected, rel=1e-12, abs=1e-15)  # one closed form, two evaluations


def test_memory_of_the_run_is_kept_between_steps_only():
    """A loose tolerance makes the pair reject steps in the contact; the memory stays the true peak."""
    sim, _ = collide([(0, 1, Thornton(K_C, DELTA_Y))], [M0, M0], 10.0, rtol=1e-5)
    assert sum(sim.stats["rejected"]) > 0  # rejected steps happened (their stages overshot or fell short)
    # rtol 1e-5 leaves errors of that order in the trajectory and so in the peak it remembers.
    assert sim.memory[-1, 0] == pytest.approx(largest_approach(10.0), rel=1e-4)
    assert np.all(np.diff(sim.memory[:, 0]) >= 0)  # a memory only grows


def test_verlet_agrees_and_scipy_methods_refuse_memory():
    sim, V = collide([(0, 1, Thornton(K_C, DELTA_Y))], [M0, M0], 10.0)
    fixed, _ = collide([(0, 1, Thornton(K_C, DELTA_Y))], [M0, M0], 10.0, method="verlet", steps_per_period=400)
    e, e_verlet = ((s.u[-1, 0] - s.u[-1, 1]) / V for s in (sim, fixed))
    # Verlet is second order and reads its memory at the step ends (not at the peak inside a step): at 400 steps
    # per period of the fastest mode its e is within 1e-3 of the pair's.
    assert e_verlet == pytest.approx(e, rel=1e-3)
    assert fixed.memory[-1, 0] == pytest.approx(sim.memory[-1, 0], rel=1e-3)  # the same reason
    with pytest.raises(ValueError, match="dopri5"):
        collide([(0, 1, Thornton(K_C, DELTA_Y))], [M0, M0], 10.0, method="odeint")


def test_bending_spring_in_series_the_restitution_the_chain_sees():
    """Two dual-spring rings (halves m0/2 joined by K_b, paper Eq. (2)) from a 5 cm drop: the bending spring
    takes part of the approach and returns it, so the contact yields less and e rises above the contact's own."""
    K_b = float(theory.bending_stiffness(R, r, E, NU))
    V = float(theory.impact_speed(0.05))
    ratio = V / V_Y
    links = [(0, 1, LinearSpring(K_b)), (1, 2, Thornton(K_C, DELTA_Y)), (2, 3, LinearSpring(K_b))]
    sim, _ = collide(links, [M0 / 2] * 4, ratio, struck=2)
    centre = sim.u[-1].reshape(2, 2).mean(axis=1)
    e_chain = (centre[0] - centre[1]) / V
    e_contact = float(theory.restitution_coefficient(V, R, r, E, NU, Y=Y, m=M0 / 2))
    print(f"e: contact alone {e_contact:.3f}, with the ring bodies {e_chain:.3f}")
    assert e_contact < e_chain < 1.0
    budget = sim.energy()
    assert abs(budget.total[-1] - budget.total[0]) < 1e-6 * 0.25 * M0 * V**2  # the rtol of the run, with margin


def test_compiled_laws_match_the_numpy_laws():
    laws = [HuntCrossley(K_C, alpha=0.3), loss_factor_spring(3.3e6, eta=1e-3, omega=1e5), Thornton(K_C, DELTA_Y, 2.0)]
    e = np.array([3e-7, -1e-7, 2e-7])
    rate = np.array([-0.4, 0.2, -1e-3])
    net = Network([M0] * 4, [(k, k + 1, law) for k, law in enumerate(laws)])
    x = np.concatenate([[0.0], np.cumsum(e)])
    u = np.concatenate([[0.0], np.cumsum(rate)])
    memory = np.array([0.0, 0.0, 4 * DELTA_Y])
    a = kernels.accelerations(kernels.pack(net), x, u, g=0.0, memory=memory)
    forces = net.forces(e, rate, memory=memory)
    expected = np.diff(np.concatenate([[0.0], forces, [0.0]])) / M0  # site k pulled up by link k, down by k - 1
    assert a == pytest.approx(expected, rel=1e-12, abs=1e-12 * np.max(np.abs(expected)))  # two evaluations


def test_hunt_crossley_and_loss_factor():
    law = HuntCrossley(K_C, alpha=0.3)
    assert float(law.force(1e-6, -10.0)) == 0.0  # it never pulls: the bracket (1 + 1.5 * 0.3 * -10 < 0)
    assert float(law.force(-1e-6, 1.0)) == 0.0  # an open contact carries nothing
    spring = loss_factor_spring(2.0, eta=0.01, omega=5.0)
    # Energy lost per cycle of x = sin(w t) over 2 pi times the largest stored energy K/2 is gamma w/K = eta.
    assert spring.gamma * 5.0 / 2.0 == pytest.approx(0.01, rel=1e-15)  # one multiplication and one division
    with pytest.raises(ValueError, match="eta"):
        loss_factor_spring(2.0, eta=-1.0, omega=5.0)


def test_yielding_chain_hangs_in_its_plastic_equilibrium():
    chain = Chain.from_ring(theory.Ring.from_aspect_ratio(9.0), 8, yield_strength=Y)
    net = chain.network()
    x, u = chain.impact_state(np.zeros(1), False, True, theory.STANDARD_GRAVITY)
    memory = net.initial_memory()
    contacts = np.append(chain.contact_links, chain.support_link)
    e = net.extension(x[0])
    assert memory[0, contacts] == pytest.approx(e[contacts], rel=1e-12)  # the static approach is the memory
    assert np.all(memory[0, contacts] > chain.delta_y)  # gravity alone yields every contact (0.22 N > 0.15 N)
    a = net.accelerations(x[0], u[0])
    assert np.max(np.abs(a)) < 1e-6 * theory.STANDARD_GRAVITY  # at rest: the inverse of the laws, to rounding
    with pytest.raises(ValueError, match="dual-spring"):
        Chain.from_ring(theory.Ring.from_aspect_ratio(9.0), 8, "power-law", yield_strength=Y)


@pytest.fixture(scope="module")
def paper_runs():
    elastic = paper_chain("dual-spring")
    plastic = paper_chain("dual-spring", yield_strength=Y)
    return {name: simulate(chain, 1.5e-3, drop_height=0.05) for name, chain in (("elastic", elastic),
                                                                                ("plastic", plastic))}  # fmt: skip


def test_paper_chain_energy_budget_closes(paper_runs):
    sim = paper_runs["plastic"]
    budget = sim.energy()
    peak = np.max(budget.kinetic)
    drift = np.max(np.abs(budget.total - budget.total[0])) / peak
    print(f"energy drift {drift:.2e} of the peak kinetic energy; plastic work "
          f"{(budget.plastic[-1] - budget.plastic[0]) / peak:.3f} of it")  # fmt: skip
    assert drift < 1e-5  # the bound; rtol 3e-10 of the pair keeps it far below
    assert budget.plastic[-1] - budget.plastic[0] > 0.1 * peak  # the impact flattens the contacts further


def test_paper_chain_pulse_is_lower_with_yielding_contacts(paper_runs):
    elastic, plastic = (paper_runs[name].peak_force(12) for name in ("elastic", "plastic"))
    print(f"ring 12: elastic {elastic:.2f} N, plastic {plastic:.2f} N")
    assert plastic < 0.9 * elastic  # the loss is tens of per cent (reported above), 10 % leaves room


def test_second_impact_flattens_the_contacts_again(paper_runs):
    """Struck again, the flattened chain yields again: Thornton's law has no work hardening and keeps Hertz's
    contact radius, so a contact driven past its memory follows the same loading line (no shakedown)."""
    from ringchain.numerics import energy_shares, second_impact

    chain = paper_chain("dual-spring", yield_strength=Y)
    first = paper_runs["plastic"]
    again = simulate(second_impact(chain, first), 1.5e-3, drop_height=0.05)
    plastic_first, plastic_again = (energy_shares(s)["plastic"][-1] for s in (first, again))
    print(f"plastic work: first impact {plastic_first:.3f}, second {plastic_again:.3f} of the impact energy; "
          f"ring 12: {first.peak_force(12):.2f} N then {again.peak_force(12):.2f} N")  # fmt: skip
    contacts = np.append(chain.contact_links, chain.support_link)
    assert again.memory[0, contacts] == pytest.approx(np.max(first.memory[:, contacts], axis=0), rel=1e-12)
    struck = chain.contact_links[0]
    assert again.memory[-1, struck] > again.memory[0, struck]  # the struck contact flattens further
    assert plastic_again > 0.5 * plastic_first  # the measured ratio is printed (near 1): most is lost again
    assert abs(energy_shares(again)["closure"][-1]) < 1e-5  # the budget closes as for the first impact


def test_from_rings_takes_a_yield_strength_per_ring():
    ring = theory.Ring.from_aspect_ratio(9.0)
    chain = Chain.from_rings([ring] * 4, yield_strength=[Y, Y, 4 * Y, 4 * Y])
    # delta_y scales as Y^2 (F_y ~ Y^3, delta ~ F^(2/3)); a contact yields where its softer ring does.
    assert chain.delta_y[0] == pytest.approx(DELTA_Y, rel=1e-9)  # the same first_yield, other rounding
    assert chain.delta_y[-1] == pytest.approx(16 * DELTA_Y, rel=1e-9)  # the same, times (4 Y / Y)^2
    assert chain.delta_y[1] == pytest.approx(DELTA_Y, rel=1e-9)  # rings 1 (Y) and 2 (4 Y): the softer
