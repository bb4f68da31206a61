"""The compiled fields (ringchain.numerics.engine.fields) against the NumPy path of the network they read.

The reference is Network.link_forces and Network.energy (NumPy, written independently of the kernels), on the
same states: seeded random displacements and velocities (half the contacts engaged, half open), every law kind,
a 1D chain, a 2D network with periodic images and anchors, a clamped and a periodic sheet, a stack; then runs of
sheets read through their results (SheetSimulation.link_force and energy(), a batch, a record of some sites).

Tolerances: the two paths evaluate the same formulas in another order (the rate as du.(b + w)/|b + w| against
du.((b + w)/|b + w|); the elastic energy as F_e delta/(n + 1) from the force against K delta^(n+1)/(n+1); sums over
the links in another order), so they agree to a few units in the last place of each term (measured: 3e-15 of the
largest value of a field at worst); 1e-12 leaves a margin of 300 over those roundings.
"""

import numpy as np
import pytest
from ringchain.numerics import ANCHOR, Links, Network, Sheet, laws, simulate, simulate_batch
from ringchain.numerics.engine import fields
from ringchain.theory import Ring

RING = Ring.from_aspect_ratio(9.0)
ROUND_OFF = 1e-12  # of a field's largest value: see the module notes

LAWS = {
    "power law": laws.PowerLaw(4.9e6, 1.11),
    "Hertz with a dashpot": laws.PowerLaw(7.5e9, 1.5, 0.02),
    "linear spring with a dashpot": laws.LinearSpring(3.3e6, 0.01),
    "dashpot": laws.Dashpot(0.03),
    "Hunt-Crossley": laws.HuntCrossley(7.5e9, alpha=0.3),
    "Thornton": laws.Thornton(7.5e9, 2e-6, 0.01),
}


def close(compiled, reference):
    scale = max(float(np.max(np.abs(reference))), 1e-300)
    np.testing.assert_allclose(compiled, reference, rtol=0, atol=ROUND_OFF * scale)


def grid(law, periodic):
    """A 4 x 4 grid of sites 10 mm apart linked along x and y (two sets: ``law`` and a power law), its edges tied
    to fixed points, or wrapping around to periodic images, the links prestretched by 2 um."""
    n, a = 4, 0.01
    r, c = np.divmod(np.arange(n * n), n)
    positions = np.stack([c * a, r * a], axis=-1).astype(float)
    i, j, anchor, shift = [], [], [], []
    for dr, dc in ((0, 1), (1, 0)):
        r2, c2 = r + dr, c + dc
        inside = (r2 < n) & (c2 < n)
        i.append(np.arange(n * n)), anchor.append(positions + np.array([dc * a, dr * a]))
        j.append(np.where(inside, (r2 % n) * n + c2 % n, (r2 % n) * n + c2 % n if periodic else ANCHOR))
        shift.append(np.where(inside[:, None] | (not periodic), 0.0, [dc * n * a, dr * n * a]))
    i, j, anchor, shift = (np.concatenate(p) for p in (i, j, anchor, shift))
    half = i.size // 2
    parts = [slice(0, half), slice(half, None)]
    other = laws.PowerLaw(4.9e6, 1.11, 0.01)
    sets = [Links(i[s], j[s], p, anchor=anchor[s], shift=shift[s], prestretch=2e-6)
            for s, p in zip(parts, (law, other), strict=True)]  # fmt: skip
    return Network(np.full(n * n, 3e-3), sets, weight_mass=np.full(n * n, 8e-3), dim=2, positions=positions)


def chain(law):
    """Six sites on a line, the last tied to the support; links alternate ``law`` and a power law."""
    other = laws.PowerLaw(4.9e6, 1.11)
    return Network(np.full(6, 3e-3), [(k, k + 1 if k < 5 else ANCHOR, law if k % 2 else other) for k in range(6)])


def states(net, seed, T=7, scale=2e-6):
    """T random displacements (m) and velocities (m/s) of every coordinate of ``net``: about half the links engaged."""
    rng = np.random.default_rng(seed)
    return rng.normal(scale=scale, size=(T, net.n_coords)), rng.normal(scale=0.3, size=(T, net.n_coords))


def memories(net, x, seed):
    """A memory per link and sample for laws with one (m): some below, some beyond the links' extensions."""
    if not net.stateful:
        return None
    rng = np.random.default_rng(seed)
    return np.abs(net.extension(x)) * rng.uniform(0.0, 3.0, size=(x.shape[0], net.n_links))


@pytest.mark.parametrize("kind", list(LAWS))
@pytest.mark.parametrize("layout", ["1D chain", "2D anchored", "2D periodic"])
def test_forces_and_energies_are_the_numpy_ones(kind, layout):
    law = LAWS[kind]
    net = chain(law) if layout == "1D chain" else grid(law, periodic=layout == "2D periodic")
    x, u = states(net, 1)
    memory = memories(net, x, 2)
    got = fields.fields(net, x, u, memory=memory, g=9.81, energies=True)
    close(got.force, net.link_forces(x, u, memory=memory))
    budget = net.energy(x, u, x[:1], 9.81, np.zeros(x.shape[0]), memory=memory)
    for name in ("kinetic", "contact", "bending", "gravity", "plastic"):
        close(getattr(got, name), getattr(budget, name))
    assert np.any(got.force == 0.0) or not law.one_sided, "some contacts open"  # the states reach both branches
    assert np.any(got.force > 0.0)


def test_forces_of_some_links_from_some_sites():
    net = grid(LAWS["Hertz with a dashpot"], periodic=False)
    x, u = states(net, 3)
    sites = np.array([0, 1, 4, 5, 6])
    links = np.flatnonzero(np.isin(net.i, sites) & (net.anchored | np.isin(net.j, sites)))
    columns = (sites[:, None] * 2 + np.arange(2)).ravel()
    got = fields.fields(net, x[:, columns], u[:, columns], links=links, sites=sites)
    close(got.force, net.link_forces(x, u, links))
    assert got.contact is None
    with pytest.raises(ValueError, match="need sites that were not recorded"):
        fields.fields(net, x[:, columns], u[:, columns], links=[net.n_links - 1], sites=sites)
    with pytest.raises(ValueError, match="the energies need every site"):
        fields.fields(net, x[:, columns], u[:, columns], links=links, sites=sites, energies=True)


def test_a_member_of_a_stack_takes_its_own_parameters():
    nets = [grid(laws.PowerLaw(K, 1.3, 0.01), periodic=True) for K in (2e6, 9e6)]
    stack = Network.stack(nets)
    x, u = states(nets[0], 4)
    for b, net in enumerate(nets):
        got = fields.fields(stack, x, u, member=b, energies=True)
        close(got.force, net.link_forces(x, u))
        close(got.contact, net.energy(x, u, x[:1], 0.0, np.zeros(x.shape[0])).contact)


@pytest.mark.parametrize("boundary", ["clamped", "periodic"])
def test_a_sheet_run_reads_its_fields_compiled(boundary):
    sheet = Sheet.square(5, 6, RING, pretension=2.0, boundary=boundary, gamma=0.01, m_eff_ratio=0.37)
    sheet = sheet.struck_at([sheet.site(0, 3)], impact_direction=-np.pi / 2)
    run = simulate(sheet, 2e-4, impact_velocity=0.5, n_samples=21)
    assert run._fields is not None  # the compiled path served this run
    net = run.network
    close(run.link_force, net.link_forces(run.x, run.u))
    budget = run.energy()
    reference = net.energy(run.x, run.u, run.x[:1], run.g, run.dissipated)
    for name in ("kinetic", "contact", "bending", "gravity"):
        close(getattr(budget, name), getattr(reference, name))
    close(budget.total, reference.total)


def test_a_batch_and_a_record_of_some_sites():
    sheet = Sheet.square(4, 5, RING, hanging=True, m_eff_ratio=0.37)
    batch = simulate_batch(sheet, 2e-4, impact_velocities=[0.2, 0.5], n_samples=11)
    net = batch.network
    close(batch.link_force, net.link_forces(batch.x, batch.u))
    close(batch.energy().gravity, net.energy(batch.x, batch.u, batch.x[:, :1], batch.g, batch.dissipated).gravity)
    close(batch[1].link_force, batch.link_force[1])
    sites = sheet.link_sites([0, 1, 2])
    some = simulate(sheet, 2e-4, impact_velocity=0.5, n_samples=11, rings=sites)
    close(some.link_force, net.link_forces(some.x, some.u, some.links, some.sites))
    with pytest.raises(ValueError, match="needs every site"):
        some.energy()


def test_chains_keep_the_numpy_path():
    run = simulate(chain(LAWS["power law"]), 1e-4, initial=states(chain(LAWS["power law"]), 5, T=1), n_samples=5)
    assert run._fields is None
