r"""The striker: the inertia of the struck ring 0 (``striker_mass``), its momentum and the impact law.

1. Every constructor takes ``striker_mass`` ("m_eff", the paper's convention and the default;
   "m0", the ring's own mass, a rigid ring in free fall; or kg), ring 0's sites carry it, and
   chains copied with other parameters keep a striker given in kg while the paper's convention
   follows ``m``.
2. The initial momentum of a run is the striker's mass times the impact speed, summed over the
   site masses and velocities of the network, and its kinetic energy half that times v0.
3. The impact law (:func:`ringchain.theory.impact_amplitude`, energy conservation) with a rigid
   striker against the lattice: the paper's chain (Table I, R/r = 9, n = 1.11, m_eff = 0.37 m0),
   unstretched and 460 rings long, struck at sqrt(2 g h) for h = 50 mm; the formed wave read
   at contacts 200 and 240 (its support spans 18 rings, so it has formed long before).  Measured:

       striker                 m_s/m    lattice/law    the wave
       m_eff (paper's)         1        -1.36 %        one wave, the striker recoils
       m0 (rigid)              2.70     -2.31 %        a train: 88.7 N, then 16.0 N, 4.8 N, ... (contact 100)

   The lattice is scale invariant (tests/numerics/layouts/test_linear_waves.py), so these ratios hold at
   every drop height and stiffness for this n and mass ratio.  A striker heavier than a ring
   keeps moving after the first wave leaves and launches smaller ones behind it, which take the
   energy the leading wave lacks; the law, which gives all the energy to one wave, is then a
   little higher still.
4. The sweep's points, the command line (``--striker-mass`` on simulate, sweep and fit traces)
   and the trace fit's round trip with a rigid striker.
"""

import dataclasses
import json

import numpy as np
import pytest
from ringchain.numerics import STRIKERS, Chain, initial_state, paper_chain, signals, simulate
from ringchain.numerics.cli.commands import main
from ringchain.numerics.jobs.sweep import FilePoint, Point, run_points
from ringchain.numerics.layouts.chain import default_t_end, striker_convention
from ringchain.numerics.layouts.chain_file import parse_chain
from ringchain.theory import Ring, impact_amplitude, impact_speed, solitary_wave_speed

RING = Ring.from_aspect_ratio(9.0)
M0 = RING.mass
CHAIN_FILE = """
[[segment]]
rings = 4
R = 22.5e-3
r = 2.5e-3
[[segment]]
rings = 4
R = [20e-3, 15e-3]
r = 2.5e-3
"""


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


# -- 1. the API -----------------------------------------------------------------------------------------
def constructors(striker_mass):
    """Each constructor of a chain of R/r = 9 rings with m_eff = 0.37 m0 (gravity on m0), struck by ``striker_mass``."""
    other = Ring.from_aspect_ratio(6.0)
    s = {"striker_mass": striker_mass}
    return {
        "power_law": Chain.power_law(5, 4.9e6, 1.11, 0.37 * M0, RING.spacing, m_gravity=M0, **s),
        "dual_spring": Chain.dual_spring(5, RING.K_c, RING.K_b, 0.37 * M0, RING.spacing, m_gravity=M0, **s),
        "from_ring": Chain.from_ring(RING, 5, "power-law", m_eff_ratio=0.37, **s),
        "from_ring dual": Chain.from_ring(RING, 5, m_eff_ratio=0.37, **s),
        "from_rings": Chain.from_rings([RING, RING, other, other], m_eff_ratio=0.37, **s),
        "graded": Chain.graded(RING, 5, aspect_ratio=(9.0, 6.0), m_eff_ratio=0.37, **s),
        "alternating": Chain.alternating(RING, other, 5, model="power-law", m_eff_ratio=0.37, **s),
        "paper_chain": paper_chain("dual-spring", stiffness="table", **s),
        "chain file": parse_chain(CHAIN_FILE).chain("power-law", 0.37, striker_mass=striker_mass),
    }


@pytest.mark.parametrize("name", list(constructors(None)))
def test_every_constructor_takes_the_striker(name):
    paper = constructors(None)[name]
    for convention in ("m_eff", "m0", 0.05):
        chain = constructors(convention)[name]
        m0, m_eff = chain.profile("m_gravity")[0], chain.profile("m")[0]
        expected = {"m_eff": m_eff, "m0": m0}.get(convention, convention)
        assert chain.striker_inertia == expected
        mass = chain.network().mass
        k = chain.sites_per_ring
        # Ring 0's sites carry the striker (two halves in the dual-spring model); every other site and every
        # weight are the paper's chain's.
        assert mass[:k].sum() == pytest.approx(expected, rel=1e-15) and np.all(mass[:k] == mass[0])
        np.testing.assert_array_equal(mass[k:], paper.network().mass[k:])
        np.testing.assert_array_equal(chain.network().weight_mass, paper.network().weight_mass)
    # "m_eff" is the paper's convention, the default: the same chain as without the argument.
    assert constructors("m_eff")[name] == paper and paper.striker_mass is None
    assert constructors("m0")[name] != paper


def test_joined_chains_keep_the_striker_of_the_struck_chain():
    a = Chain.from_ring(RING, 4, "power-law", m_eff_ratio=0.37, striker_mass="m0")
    b = Chain.from_ring(RING, 4, "power-law", m_eff_ratio=0.37, striker_mass=0.05)
    joined = Chain.joined(a, b)
    assert joined.striker_inertia == M0
    # b's ring 0, now ring 4 of the joined chain, has the inertia of its ring.
    np.testing.assert_array_equal(joined.network().mass[1:], 0.37 * M0)
    assert Chain.joined(b, a).striker_inertia == 0.05
    assert Chain.joined(Chain.from_ring(RING, 4, "power-law"), a).striker_mass is None


def test_a_copied_chain_keeps_a_rigid_striker_and_the_paper_convention_follows_m():
    rigid = paper_chain("power-law", striker_mass="m0")
    paper = paper_chain("power-law")
    # The trace fits vary m by dataclasses.replace: a rigid striker is a ring of known mass, the paper's striker
    # is a lattice ring.
    assert dataclasses.replace(rigid, m=0.5 * M0).striker_inertia == M0
    assert dataclasses.replace(paper, m=0.5 * M0).striker_inertia == 0.5 * M0
    assert rigid == paper_chain("power-law", striker_mass=M0)  # "m0" is resolved to kg when the chain is built


@pytest.mark.parametrize(
    ("value", "message"),
    [
        ("M0", r"striker_mass must be one of \('m_eff', 'm0'\), got 'M0'"),
        ("0.02", r"striker_mass must be one of \('m_eff', 'm0'\), got '0.02'"),
        (0.0, r"striker_mass must be positive \(in kg\), got 0"),
        (-0.02, r"striker_mass must be positive \(in kg\), got -0.02"),
        (float("nan"), "striker_mass must be finite, got nan"),
        (True, r"striker_mass must be one mass \(in kg\) or one of \('m_eff', 'm0'\), got True"),
        ([0.01, 0.02], r"striker_mass must be one mass \(in kg\) or one of \('m_eff', 'm0'\), got \[0.01, 0.02\]"),
    ],
)
def test_a_bad_striker_is_refused(value, message):
    with pytest.raises(ValueError, match=message):
        Chain.power_law(3, 1e6, 1.5, 0.01, 0.04, striker_mass=value)
    with pytest.raises(ValueError, match=message):
        Point(striker_mass=value)


def test_striker_conventions():
    assert STRIKERS == ("m_eff", "m0")
    assert [striker_convention(x) for x in (None, "m_eff", "m0", 0.02, np.float64(0.02))] == [
        "m_eff", "m_eff", "m0", 0.02, 0.02]  # fmt: skip


# -- 2. momentum and energy of the impact ---------------------------------------------------------------
@pytest.mark.parametrize("model", ["power-law", "dual-spring"])
@pytest.mark.parametrize("striker", ["m_eff", "m0", 0.05])
def test_a_run_starts_with_the_striker_momentum(model, striker):
    chain = paper_chain(model, stiffness="table", striker_mass=striker)
    h = 0.05
    v0 = float(impact_speed(h))
    sim = simulate(chain, 2e-5, drop_height=h, n_samples=3, rings=None)
    mass = chain.network().mass
    momentum, energy = np.sum(mass * sim.u[0]), 0.5 * np.sum(mass * sim.u[0] ** 2)
    # Sums of a few products: rounding only (1e-15 relative, 1e-13 leaves a margin).
    assert momentum == pytest.approx(-chain.striker_inertia * v0, rel=1e-13)  # ring 0 moves away from the chain
    assert energy == pytest.approx(0.5 * chain.striker_inertia * v0**2, rel=1e-13)
    # The rigid striker brings the real ring's momentum m0 v0; the paper's convention 37 % of it.
    expected = {"m_eff": 0.37 * M0, "m0": M0}.get(striker, striker)
    assert chain.striker_inertia == pytest.approx(expected, rel=1e-15)
    # And an impact on the hanging chain (no drop) the same.
    _, u = initial_state(chain, impact_velocity=[0.5, 2.0])
    np.testing.assert_allclose(u @ mass, -chain.striker_inertia * np.array([0.5, 2.0]), rtol=1e-13)


def test_the_default_duration_follows_the_striker():
    """The striker stores mu v^2/2 against ring 1 (mu its reduced mass): a lighter striker, a weaker and slower
    pulse, a longer default duration; the paper's convention as before (mu = m/2)."""
    base = paper_chain("power-law")
    durations = [default_t_end(paper_chain("power-law", striker_mass=s), [1.0], (6, 12)) for s in (1e-3, "m0")]
    assert durations[0] > default_t_end(base, [1.0], (6, 12)) > durations[1]


# -- 3. the impact law with a rigid striker ---------------------------------------------------------------
@pytest.fixture(scope="module")
def formed_waves():
    """Peak forces (N) of the formed wave at contacts 200 and 240 of the paper's power-law chain, unstretched and
    460 rings long, after a 50 mm drop, for each striker; with the law's prediction."""
    paper = paper_chain("power-law", stiffness="table")
    out = {}
    for striker in STRIKERS:
        chain = Chain.power_law(460, paper.K, paper.n, paper.m, paper.a, m_gravity=paper.m_gravity, support="free",
                                striker_mass=striker)  # fmt: skip
        law = float(impact_amplitude(impact_speed(0.05), K=paper.K, n=paper.n, m=paper.m, a=paper.a,
                                     m_striker=chain.striker_inertia))  # fmt: skip
        # Until the wave has passed contact 240 at 90 % of its speed at the law's force.
        t_end = 250 * paper.a / (0.9 * float(solitary_wave_speed(law, K=paper.K, n=paper.n, m=paper.m, a=paper.a)))
        # Verlet at 200 steps per period, as the impact-law test of test_linear_waves.py (F_m changes by < 1e-5
        # with 400).
        sim = simulate(chain, t_end, drop_height=0.05, gravity=False, method="verlet", steps_per_period=200,
                       n_samples=3001)  # fmt: skip
        near, far = (signals.peak(sim.t, sim.contact_force[:, c])[1] for c in (200, 240))
        out[striker] = (near, far, law)
    return paper, out


def test_the_impact_law_with_a_rigid_striker_matches_the_lattice(formed_waves):
    paper, waves = formed_waves
    for near, far, _ in waves.values():
        assert far == pytest.approx(near, rel=1e-3)  # formed: the same peak 40 rings apart (measured 3e-7)
    near, far, law = waves["m_eff"]
    # The paper's convention: measured 1.36 % below the law (test_linear_waves.py: 1.1-1.4 % for n = 1.1-1.5).
    assert 0.98 < far / law < 1.0
    near, far, law = waves["m0"]
    # The rigid striker (m_s = 2.70 m): measured 2.31 % below the law; the heavier striker launches a train and
    # the leading wave carries 95.7 % of its energy (the law's energy at the measured force).  Tolerance 3 %, and
    # below the law.
    assert 0.97 < far / law < 1.0
    # The rigid striker's wave against the paper's: the law's (m0/m_eff)^(n/(n+1)) = 1.687, the lattice's 1.671.
    lattice_gain = waves["m0"][1] / waves["m_eff"][1]
    law_gain = (waves["m0"][2] / waves["m_eff"][2], (1 / 0.37) ** (paper.n / (paper.n + 1)))
    assert law_gain[0] == pytest.approx(law_gain[1], rel=1e-12)  # F_m ~ m_s^(n/(n+1)), test_pulse.py
    assert lattice_gain == pytest.approx(law_gain[0], rel=0.015)  # measured -0.96 %: the two misses above


# -- 4. sweeps and the command line -----------------------------------------------------------------------
def test_sweep_points_carry_the_striker():
    rows = {}
    for striker in ("m_eff", "m0", 0.05):
        point = Point(model="power-law", n_rings=14, m_eff_ratio=0.37, drop_height=0.05, striker_mass=striker)
        assert point.chain().striker_inertia == {"m_eff": 0.37 * M0, "m0": M0}.get(striker, striker)
        (rows[striker],) = run_points([point])
        assert rows[striker]["striker_mass"] == (striker if isinstance(striker, str) else "kg")
        assert rows[striker]["striker_mass_kg"] == pytest.approx(point.chain().striker_inertia, rel=1e-15)
    # Points that differ only in the striker are different chains: integrated apart, and the heavier striker
    # sends the stronger wave.
    assert len({Point(striker_mass=s, drop_height=0.05).chain_key for s in ("m_eff", "m0")}) == 2
    assert rows["m_eff"]["peak_force_near_N"] < rows[0.05]["peak_force_near_N"]
    file_point = FilePoint(parse_chain(CHAIN_FILE), model="power-law", m_eff_ratio=0.37, drop_height=0.05,
                           sensors=(2, 6), striker_mass="m0")  # fmt: skip
    (row,) = run_points([file_point])
    assert (row["striker_mass"], row["striker_mass_kg"], row["m_eff_ratio"]) == ("m0", M0, 0.37)
    assert file_point.chain_key != dataclasses.replace(file_point, striker_mass="m_eff").chain_key


def test_simulate_and_sweep_take_the_striker(capsys, tmp_path):
    out = tmp_path / "run.csv"
    code, text, err = run(capsys, "simulate", "--model", "power-law", "--m-eff-ratio", "0.37", "--drop-height",
                          "0.05", "--striker-mass", "m0", "--out", out)  # fmt: skip
    assert code == 0 and err == ""
    assert f"rigid striker of the ring's mass m0, {M0 * 1e3:.4g} g" in text
    default = run(capsys, "simulate", "--model", "power-law", "--m-eff-ratio", "0.37", "--drop-height", "0.05",
                  "--out", out)[1]  # fmt: skip
    assert "striker of the lattice's inertia m_eff (the paper's convention)" in default
    sweep_csv = tmp_path / "sweep.csv"
    code, _, err = run(capsys, "sweep", "--model", "power-law", "--m-eff-ratio", "0.37", "--drop-height", "0.05",
                       "--striker-mass", "m_eff", "m0", "0.01", "--workers", "0", "--out", sweep_csv)  # fmt: skip
    assert code == 0 and err == ""
    lines = sweep_csv.read_text().splitlines()
    header = lines[0].split(",")
    rows = [dict(zip(header, line.split(","), strict=True)) for line in lines[1:]]
    assert [row["striker_mass"] for row in rows] == ["m_eff", "m0", "kg"]
    masses = [float(row["striker_mass_kg"]) for row in rows]
    assert masses == pytest.approx([0.37 * M0, M0, 0.01], rel=1e-15)
    # The rigid striker's pulse is the strongest (the impact law: F_m ~ m_s^(n/(n+1))).
    forces = [float(row["peak_force_near_N"]) for row in rows]
    assert forces[1] > forces[2] > forces[0]


@pytest.mark.parametrize(
    ("value", "message"),
    [
        ("heavy", "argument --striker-mass: expected m_eff, m0 or a mass in kg, got 'heavy'"),
        ("-0.02", r"argument --striker-mass: striker mass must be positive (in kg), got -0.02"),
        ("0", r"argument --striker-mass: striker mass must be positive (in kg), got 0"),
        ("inf", "argument --striker-mass: striker mass must be finite, got inf"),
    ],
)
def test_a_bad_striker_is_one_line_before_any_work(capsys, tmp_path, value, message):
    for argv in (["simulate", "--drop-height", "0.05", "--out", tmp_path / "run.csv"],
                 ["sweep", "--drop-height", "0.05"],
                 ["fit", "traces", tmp_path / "missing.csv", "--drop-height", "0.05"]):  # fmt: skip
        code, out, err = run(capsys, *argv, f"--striker-mass={value}")
        assert code == 2 and out == "" and err.count("\n") == 1, err
        assert message in err, err
    assert not (tmp_path / "run.csv").exists()


def test_fit_traces_with_a_rigid_striker_recovers_m_eff(capsys, tmp_path):
    """Round trip: a drop on a chain struck by a rigid ring, fitted with the same striker (the impact's momentum
    m0 v0 does not move with m) and with the paper's (which must credit the impact to m_eff)."""
    out = tmp_path / "drop.csv"
    assert main(["simulate", "--model", "power-law", "--m-eff-ratio", "0.37", "--drop-height", "0.02",
                 "--striker-mass", "m0", "--samples", "801", "--t-end", "1.6e-3", "--out", str(out)]) == 0  # fmt: skip
    capsys.readouterr()
    fits = {}
    for striker in ("m0", "m_eff"):
        code, text, err = run(capsys, "fit", "traces", out, "--model", "power-law", "--m-eff-ratio", "0.5",
                              "--drop-height", "0.02", "--free", "m,t0", "--striker-mass", striker,
                              "--json")  # fmt: skip
        assert code == 0 and err == ""
        fits[striker] = json.loads(text)
    # Noise-free data from the same model: 1e-5 relative, as the paper-convention round trip of test_fit_cli.py;
    # the rigid striker's mass is reported as fixed.
    assert fits["m0"]["values"]["m"] / M0 == pytest.approx(0.37, rel=1e-5)
    assert fits["m0"]["fixed"]["striker_mass"] == M0 and "striker_mass" not in fits["m_eff"]["fixed"]
    # With the paper's convention and K held, the speed still pins m near 0.37 m0 (measured 0.354), but the impact
    # brings 0.37 of the energy and the pulses are too weak: the residual is 8.0 N rms against 3e-4 N (a factor
    # 27000), and the fit says so in a note.
    assert fits["m_eff"]["rms_residual_N"] > 1000 * fits["m0"]["rms_residual_N"]
    assert fits["m_eff"]["notes"] and not fits["m0"]["notes"]
    code, text, _ = run(capsys, "fit", "traces", out, "--model", "power-law", "--m-eff-ratio", "0.5",
                        "--drop-height", "0.02", "--free", "m,t0", "--striker-mass", "m0")  # fmt: skip
    assert code == 0 and "rigid striker of the ring's mass m0" in text
    assert "striker_mass = " in text  # the fixed values of the report
