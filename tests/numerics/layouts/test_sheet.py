"""Sheets of interlinked rings: the layouts, their statics, their linear waves against theory/sheet.py, the
hanging sheet against the hanging chain column by column, energy, records and NetCDF files."""

import numpy as np
import pytest
from ringchain.numerics import Chain, Sheet, read_sheet_run, simulate
from ringchain.numerics.layouts.sheet import contact_law
from ringchain.theory import Ring, sheet_dispersion

RING = Ring.from_aspect_ratio(9.0)


# --- layouts and statics --------------------------------------------------------------------------------


def test_square_layout_sites_edges_and_links():
    sheet = Sheet.square(3, 4, RING, hanging=True)
    assert sheet.site(2, 1) == 9 and sheet.edge("left").tolist() == [0, 4, 8]
    links = sheet.links
    # 3 rows of 3 horizontal links, 2 x 4 vertical links inside, 4 to the support (far end -1).
    assert np.sum(sheet.link_family == 0) == 9 and np.sum(sheet.link_family == 1) == 12
    assert sheet.support_links.size == 4 and np.all(links[sheet.support_links, 1] == -1)
    assert np.allclose(sheet.network().rest_lengths, RING.spacing, rtol=1e-15)  # just taut, a = 2(R - r)
    with pytest.raises(ValueError, match="not in a sheet of 3 rows"):
        sheet.site(3, 0)


@pytest.mark.parametrize(
    ("build", "message"),
    [
        (lambda: Sheet.square(3, 3, RING, model="dual-spring"), "no counterpart"),
        (lambda: Sheet.triangular(4, 4, RING, hanging=True), "periodic"),
        (lambda: Sheet.square(3, 3, RING, hanging=True, pretension=1.0), "not both"),
        (lambda: Sheet.triangular(3, 4, RING, boundary="periodic"), "even number of rows"),
        (lambda: Sheet.square(3, 3, RING, pretension=(1.0, 2.0, 3.0)), "tuple of 2"),
        (lambda: Sheet.square(3, 3, RING, struck=[4]), "no single edge"),
        (lambda: Sheet.square(3, 3, RING, struck=[9]), "site indices in 0..8"),
    ],
)
def test_bad_sheets_are_refused_with_a_reason(build, message):
    with pytest.raises(ValueError, match=message):
        build()


@pytest.mark.parametrize(
    "sheet",
    [
        Sheet.square(5, 4, RING, hanging=True),
        Sheet.square(4, 4, RING, hanging=True, boundary="periodic"),
        Sheet.triangular(5, 4, RING, hanging=True, boundary="periodic"),
        Sheet.square(4, 5, RING, pretension=(2.0, 3.0)),
        Sheet.triangular(4, 5, RING, pretension=(2.0, 3.0, 1.0)),
        Sheet.triangular(4, 5, RING, pretension=2.0, boundary="periodic"),
    ],
    ids=lambda sheet: f"{sheet.pattern} {'hanging' if sheet.hanging else 'flat'} {sheet.boundary}",
)
def test_the_static_state_is_an_equilibrium(sheet):
    x = sheet.static_state()
    F = sheet.network().accelerations(x) * sheet.m
    tension = sheet.static_tension()
    # Forces of links carrying up to max(T) cancel to rounding (1e-13 of it); gravity is in the accelerations.
    assert np.abs(F).max() < 1e-13 * tension.max()
    e = sheet.network().extension(x)
    assert np.allclose(sheet.network().forces(e), tension, rtol=1e-12, atol=1e-13 * tension.max())


def test_a_pretension_of_zero_leaves_every_link_just_taut():
    sheet = Sheet.triangular(3, 3, RING)
    assert np.all(sheet.network().extension(np.zeros(18)) == 0.0)


def test_from_links_checks_the_balance_of_tensions():
    a = RING.spacing
    positions = [[0.0, 0.0], [a, 0.0], [2 * a, 0.0]]
    anchors = np.array([[-a, 0.0], [0.0, 0.0], [0.0, 0.0], [3 * a, 0.0]])
    line = Sheet.from_links(positions, [[0, -1], [0, 1], [1, 2], [2, -1]], RING, tension=2.0, anchors=anchors)
    assert np.allclose(line.network().forces(line.network().extension(np.zeros(6))), 2.0, rtol=1e-13)
    with pytest.raises(ValueError, match="do not balance at site 0"):
        Sheet.from_links(positions, [[0, -1], [0, 1], [1, 2], [2, -1]], RING, tension=[1.0, 2.0, 2.0, 2.0],
                         anchors=anchors)  # fmt: skip


def test_contact_law_is_the_chains_and_falls_back_to_the_numerical_contact():
    assert contact_law(RING) == RING.power_law()
    oblique = contact_law(RING, angle=1.0)
    assert oblique[0] != RING.power_law()[0]
    other = Ring.from_aspect_ratio(6.0)
    K, n = contact_law(RING, other)
    assert 1.0 < n < 1.5 and K > 0


# --- linear waves -----------------------------------------------------------------------------------------


def hessian(sheet):
    """d^2 E/dx dx of the network at its pretensioned state, assembled link by link from Network.stiffness and
    the geometry: k e e^T along the link plus (F/l)(I - e e^T) across it (the second derivative of V(|b + w|))."""
    net = sheet.network()
    e, _, direction = net.geometry(np.zeros(net.n_coords))
    k, F = net.stiffness(e), net.forces(e)
    length = net.spans + 0.0  # at x = 0 the ends sit at their rest positions
    H = np.zeros((net.n_coords, net.n_coords))
    for link in range(net.n_links):
        u = direction[link]
        block = k[link] * np.outer(u, u) + F[link] / length[link] * (np.eye(2) - np.outer(u, u))
        i, j = net.i[link], net.j[link]
        H[2 * i : 2 * i + 2, 2 * i : 2 * i + 2] += block
        if j >= 0:
            H[2 * j : 2 * j + 2, 2 * j : 2 * j + 2] += block
            H[2 * i : 2 * i + 2, 2 * j : 2 * j + 2] -= block
            H[2 * j : 2 * j + 2, 2 * i : 2 * i + 2] -= block
    return H


def allowed_wavevectors(sheet):
    """Wavevectors of the Bloch waves that fit a periodic sheet: q.P = 2 pi (integer) for both periods P."""
    rows, cols = sheet.shape
    shifts = sheet.network().shifts
    # The two periods: the links that wrap along x only, and those that wrap along y only (x shift 0).
    periods = np.diag([shifts[shifts[:, 1] == 0][:, 0].max(), shifts[shifts[:, 0] == 0][:, 1].max()])
    n = np.stack(np.meshgrid(np.arange(cols), np.arange(rows), indexing="ij"), -1).reshape(-1, 2)
    return 2 * np.pi * np.linalg.solve(periods, n.T).T


def theory_parameters(sheet):
    """k, T, m, a of sheet_dispersion from the sheet's own links (uniform pretension)."""
    net = sheet.network()
    law, e = net.law_of(0), net.prestretch[0]
    return dict(k=float(law.stiffness(e)), T=float(law.force(e)), m=sheet.m, a=float(net.spans[0]))


@pytest.mark.parametrize("pattern", ["square", "triangular"])
def test_dispersion_equals_the_eigenvalues_of_the_linearised_sheet(pattern):
    build = Sheet.square if pattern == "square" else Sheet.triangular
    sheet = build(6, 5, RING, pretension=3.0, boundary="periodic", m_eff_ratio=0.37)
    H = hessian(sheet)
    # The Hessian assembled from the links is the network's: minus the mass times d(acceleration)/dx, central
    # differences of 1e-10 m (error ~ h^2 of the third derivative plus rounding eps F/h: 1e-6 of the largest entry).
    net, h = sheet.network(), 1e-10
    columns = [-(net.accelerations(h * d, g=0.0) - net.accelerations(-h * d, g=0.0)) / (2 * h) * sheet.m
               for d in np.eye(net.n_coords)[:6]]  # fmt: skip
    assert np.allclose(np.array(columns).T, H[:, :6], rtol=0, atol=1e-6 * np.abs(H).max())
    lattice = np.sort(np.linalg.eigvalsh(H / sheet.m))
    theory = np.sort((sheet_dispersion(*allowed_wavevectors(sheet).T, pattern=pattern,
                                       **theory_parameters(sheet)) ** 2).ravel())  # fmt: skip
    # eigvalsh is backward stable: each eigenvalue within a few eps of the largest (1e-9 leaves room); the
    # rigid translations are the two zero frequencies at q = 0 on both sides.
    assert np.allclose(lattice, theory, rtol=0, atol=1e-9 * lattice.max())


@pytest.mark.parametrize(("pattern", "branch"), [("square", 0), ("square", 1), ("triangular", 0), ("triangular", 1)])
def test_measured_frequency_of_a_plane_wave_agrees_with_the_dispersion(pattern, branch):
    """A small standing wave cos(q x), polarised along x (longitudinal) or y (transverse), on a periodic sheet:
    along x both sheets' Bloch matrices are diagonal (theory/sheet.py), so it is a mode of the lattice."""
    build = Sheet.square if pattern == "square" else Sheet.triangular
    sheet = build(4, 8, RING, pretension=3.0, boundary="periodic", m_eff_ratio=0.37)
    params = theory_parameters(sheet)
    q = 2 * np.pi * 2 / (8 * params["a"])  # two wavelengths along the 8 columns
    net = sheet.network()
    mode = np.zeros((sheet.n_sites, 2))
    mode[:, 1 - branch] = np.cos(q * net.positions[:, 0])  # branch 0 (slower): transverse, along y
    amplitude = 1e-3 * float(net.prestretch[0])  # 1e-3 of the static extension: nonlinear shift ~ 1e-6
    omega = sheet_dispersion(q, 0.0, pattern=pattern, **params)[branch]
    period = 2 * np.pi / omega
    t = np.linspace(0.0, 2 * period, 401)
    run = simulate(sheet, t[-1], initial=(amplitude * mode.ravel(), np.zeros(mode.size)), t_eval=t, rtol=1e-12,
                   gravity=False)  # fmt: skip
    projection = np.einsum("tsc,sc->t", run.displacement, mode) / np.sum(mode**2) / amplitude
    from scipy.optimize import least_squares

    fit = least_squares(lambda p: p[0] * np.cos(p[1] * omega * t) - projection, [1.0, 1.0], xtol=1e-15, ftol=1e-15)
    # Two periods at rtol 1e-12 and an amplitude 1e-3 of the static stretch: 1e-5 covers the amplitude's
    # frequency shift and the fit (found below 1e-7).
    assert fit.x[1] == pytest.approx(1.0, rel=1e-5)


# --- the hanging sheet is a row of chains ------------------------------------------------------------------


def column_links(sheet, col):
    """The vertical links of column ``col`` from the bottom up, the support's last: the chain's contacts."""
    net = sheet.network()
    cols = sheet.shape[1]
    links = np.flatnonzero((sheet.link_family == 1) & (net.i % cols == col))
    return links[np.argsort(net.i[links])]


def struck_hanging(method, **options):
    rows, cols = 8, 4
    sheet = Sheet.square(rows, cols, RING, hanging=True, m_eff_ratio=0.37)
    chain = Chain.from_ring(RING, rows, "power-law", m_eff_ratio=0.37)
    runs = [simulate(model, 1.5e-3, drop_height=0.05, method=method, n_samples=301, **options)
            for model in (chain, sheet)]  # fmt: skip
    return sheet, runs[0].bond_force, runs[1].link_force


def test_hanging_square_sheet_struck_along_its_bottom_row_is_a_row_of_chains_verlet():
    sheet, chain, forces = struck_hanging("verlet", dt=2e-7)
    peak = chain.max()
    for col in range(sheet.shape[1]):
        # One explicit step on both: the sheet's extensions (2 b.w + w.w)/(l + L0) and its forces divided by
        # the mass after summing differ from the chain's by rounding, carried through 7500 steps (found 2e-14).
        assert np.allclose(forces[:, column_links(sheet, col)], chain, rtol=0, atol=1e-12 * peak)
    assert np.all(forces[:, sheet.link_family == 0] == 0.0)  # the side links stay at rest


def test_hanging_square_sheet_struck_along_its_bottom_row_is_a_row_of_chains_dopri5():
    sheet, chain, forces = struck_hanging("dopri5")
    peak = chain.max()
    for col in range(sheet.shape[1]):
        # The max-norm error control takes the same steps for the sheet as for the chain (idle components,
        # the side links and the x motions, do not change them): the 1e-6 of the peak.
        assert np.allclose(forces[:, column_links(sheet, col)], chain, rtol=0, atol=1e-6 * peak)
    assert np.abs(forces[:, sheet.link_family == 0]).max() <= 1e-6 * peak


# --- the point impact: what reaches the rings off the struck column -------------------------------------------


def test_the_motion_off_the_struck_column_is_second_order_in_the_impact():
    """A ring struck along the square sheet's column moves the rings beside the column only at second order.

    Linearised, the rings of the next columns feel the column through the geometric stiffness T/a alone, a wave
    of speed c_T (about 3 m/s here, under a millimetre in the run). To second order the column's motion u_y
    stretches each link across by u_y^2/(2a), which pushes the next column along x at the axial stiffness k
    (book chapter "Sheets"). Struck away from the sheet and into it (every link stays taut at these speeds), the
    column's motion changes sign and the second-order push does not: the rings beside the column move by the
    part even in the impact, and their peak speed over the impact speed grows in proportion to it.
    """
    sheet = Sheet.square(9, 7, RING, pretension=2.0, m_eff_ratio=0.37)
    struck = sheet.site(0, 3)
    offset = np.rint((sheet.positions - sheet.positions[struck]) / RING.spacing).astype(int)
    beside = (np.abs(offset[:, 0]) >= 2) & (offset[:, 1] >= 1) & (np.abs(offset[:, 0]) + offset[:, 1] <= 5)
    peaks, odd_share = {}, {}
    for speed in (0.005, 0.01):
        velocity = {}
        for sign in (1.0, -1.0):
            run = simulate(sheet.struck_at([struck], impact_direction=(0.0, -sign)), 3e-4, impact_velocity=speed,
                           method="verlet", n_samples=301)  # fmt: skip
            velocity[sign] = run.velocity[:, beside]
        even, odd = (velocity[1.0] + velocity[-1.0]) / 2, (velocity[1.0] - velocity[-1.0]) / 2
        odd_share[speed] = np.abs(odd).max() / np.abs(even).max()
        peaks[speed] = np.linalg.norm(velocity[1.0], axis=-1).max() / speed
    # Measured: the odd part is 1.6 % and 3.3 % of the even part (it is third order: it doubles with the speed);
    # a first-order leak would be the larger part. 10 % leaves room for the step and the sampling.
    assert odd_share[0.005] < 0.1 and odd_share[0.01] < 0.1
    # Peak ring speed over impact speed doubles when the impact speed doubles (measured 2.03: the third-order
    # part adds 1-3 %); a first-order motion would keep the ratio, a third-order one quadruple it.
    assert peaks[0.01] / peaks[0.005] == pytest.approx(2.0, rel=0.05)


# --- energy, records, files --------------------------------------------------------------------------------


@pytest.mark.parametrize("pattern", ["square", "triangular"])
def test_energy_is_conserved_without_dashpots(pattern):
    build = Sheet.square if pattern == "square" else Sheet.triangular
    sheet = build(6, 6, RING, pretension=2.0, m_eff_ratio=0.37)
    sheet = sheet.struck_at([sheet.site(0, 2)])
    run = simulate(sheet, 1e-3, impact_velocity=0.5, rtol=1e-12, n_samples=101)
    energy = run.energy()
    impact = 0.5 * sheet.m * 0.5**2
    # odeint at rtol = 1e-12 (atol 1e-12 of the run's scales): the 1e-8 of the impact energy.
    assert np.max(np.abs(energy.total - energy.total[0])) < 1e-8 * impact
    assert energy.kinetic[-1] < 0.9 * impact  # the energy did spread into the links


def test_hanging_sheet_energy_with_gravity_is_conserved():
    sheet = Sheet.square(5, 4, RING, hanging=True, m_eff_ratio=0.37).struck_at("bottom")
    run = simulate(sheet, 1e-3, drop_height=0.02, rtol=1e-12, n_samples=51)
    energy = run.energy()
    impact = 4 * 0.5 * sheet.m * (2 * 9.80665 * 0.02)
    assert np.max(np.abs(energy.total - energy.total[0])) < 1e-8 * impact  # as above, with gravity's work


def test_damped_sheet_dissipates_and_a_velocity_field_strikes():
    sheet = Sheet.triangular(4, 4, RING, pretension=2.0, gamma=0.2)
    field = np.zeros((sheet.n_sites, 2))
    field[sheet.edge("left"), 0] = -1.0
    run = simulate(sheet.struck_at(field), 5e-4, impact_velocity=0.3, rtol=1e-10, n_samples=51)
    assert np.allclose(run.velocity[0][sheet.edge("left")], [-0.3, 0.0])
    energy = run.energy()
    assert energy.dissipated[-1] > 0 and np.allclose(energy.total, energy.total[0], rtol=1e-7)


def test_records_of_some_sites_give_the_forces_of_their_links(tmp_path):
    sheet = Sheet.square(5, 5, RING, pretension=2.0, m_eff_ratio=0.37)
    sheet = sheet.struck_at([sheet.site(0, 2)])
    full = simulate(sheet, 4e-4, impact_velocity=0.5, method="verlet", n_samples=41)
    wanted = np.flatnonzero(sheet.link_family == 1)[:5]
    part = simulate(sheet, 4e-4, impact_velocity=0.5, method="verlet", n_samples=41, rings=sheet.link_sites(wanted))
    hit = np.isin(part.links, wanted)
    assert np.all(np.isin(wanted, part.links))
    assert np.array_equal(part.link_force[:, hit], full.link_force[:, part.links[hit]])
    with pytest.raises(ValueError, match="needs every site"):
        part.energy()
    path = tmp_path / "run.nc"
    full.to_netcdf(path, every=2)
    data = read_sheet_run(path)
    assert data.attrs["pattern"] == "square" and data.attrs["rows"] == 5
    assert np.array_equal(data["link_force"].values, full.link_force[::2])
    assert np.array_equal(data["displacement"].values, full.displacement[::2])
    assert data["link_force"].attrs["units"] == "N" and data["time"].values[1] == full.t[2]
    assert np.array_equal(data["energy_kinetic"].values, full.energy().kinetic[::2])
