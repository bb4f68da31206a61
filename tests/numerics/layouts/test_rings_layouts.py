"""Layouts of rigid rings in 3D, their rest-pose check, their static state and their files.

Independent references: linking numbers counted by piercing (the signed crossings of one circle
through the other's disc, found here on a fine polygon, not with the package's functions), tube
gaps by dense sampling of both centre circles, the chain's spacing 2(R - r) from the geometry of two
perpendicular circles, the hanging chain's approach (F / K)^(1/n) with F the weight below the contact.
"""

import numpy as np
import pytest
from ringchain.numerics.contact.tori import torus_contacts
from ringchain.numerics.layouts.rings import Rings
from ringchain.numerics.layouts.rings_files import (
    read_rings_run,
    rings_dataset,
    torus_mesh,
    write_rings_netcdf,
    write_rings_vtk,
)
from ringchain.numerics.layouts.rings_layouts import (
    chain_layout,
    check_links,
    mail_geometry,
    mail_layout,
    pam_layout,
    rotate,
)
from ringchain.theory import STANDARD_GRAVITY, Ring

RING = Ring(0.0225, 0.0025)  # the paper's R/r = 9 ring, stainless steel


def circle(centre, q, R, count):
    """``count`` points of the centre circle of a ring (body xy plane, radius R) in space."""
    s = 2 * np.pi * np.arange(count) / count
    body = np.stack([R * np.cos(s), R * np.sin(s), np.zeros(count)], axis=1)
    return rotate(np.broadcast_to(q, (count, 4)), body) + centre


def pierce(c1, q1, R1, c2, q2, R2, count=2000):
    """Linking number: signed crossings of circle 2 (as a closed polygon) through the flat disc of circle 1."""
    axis = rotate(q1, [0.0, 0.0, 1.0])
    points = circle(c2, q2, R2, count)
    nxt = np.roll(points, -1, axis=0)
    h0, h1 = (points - c1) @ axis, (nxt - c1) @ axis
    total = 0
    for k in np.flatnonzero((h0 < 0) != (h1 < 0)):
        x = points[k] + h0[k] / (h0[k] - h1[k]) * (nxt[k] - points[k])
        if np.linalg.norm(x - c1) < R1:
            total += 1 if h1[k] > h0[k] else -1
    return total


def sampled_gap(c1, q1, c2, q2, ring=RING, count=600):
    """Least distance of the two centre circles by dense sampling of both, less 2r (m)."""
    a, b = circle(c1, q1, ring.R, count), circle(c2, q2, ring.R, count)
    distance = np.sqrt(((a[:, None, :] - b[None, :, :]) ** 2).sum(-1)).min()
    return distance - 2 * ring.r


# Sampling both circles at spacing h = 2 pi R / count overestimates the least distance by at most
# h^2 / 4 / (curvature-adjusted) ~ (2 pi R / count)^2 / R: about 2.4e-6 m at R = 22.5 mm and count = 600.
SAMPLING = (2 * np.pi * RING.R / 600) ** 2 / RING.R


def near_pairs(centres, ring=RING):
    n = len(centres)
    return [(i, j) for i in range(n) for j in range(i + 1, n)
            if np.linalg.norm(centres[i] - centres[j]) < 2 * (ring.R + ring.r)]  # fmt: skip


def assert_valid(centres, orientations, links, ring=RING):
    intended = {tuple(sorted(p)) for p in links.tolist()}
    for i, j in near_pairs(centres, ring):
        lk = pierce(centres[i], orientations[i], ring.R, centres[j], orientations[j], ring.R)
        assert abs(lk) == (1 if (i, j) in intended else 0), (i, j, lk)
        assert sampled_gap(centres[i], orientations[i], centres[j], orientations[j], ring) >= -1e-12, (i, j)


def test_chain_spacing_is_two_R_minus_r_from_the_geometry():
    centres, orientations, links = chain_layout(5, RING)
    axes = rotate(orientations, [0.0, 0.0, 1.0])
    # Perpendicular planes, each turned 90 degrees about the chain's axis z from the next.
    np.testing.assert_allclose(np.abs(np.sum(axes[:-1] * axes[1:], axis=1)), 0.0, atol=1e-15)  # rounding
    np.testing.assert_allclose(axes[:, 2], 0.0, atol=1e-15)  # rounding: axes horizontal
    # Two perpendicular circles through each other's centre line: the far wire of one sits at height a - R
    # above the other's centre, the near wire of the other at R, so they touch when a - R - R = -2r... i.e. the
    # inner points R - r from both centres: a = 2(R - r), and the sampled tube gap is zero.
    np.testing.assert_allclose(np.diff(centres[:, 2]), 2 * (RING.R - RING.r), rtol=1e-15)  # rounding
    gap = sampled_gap(centres[0], orientations[0], centres[1], orientations[1])
    assert -1e-12 <= gap <= SAMPLING
    assert_valid(centres, orientations, links)


def test_mail_4in1_every_intended_pair_linked_no_other_and_no_overlap():
    centres, orientations, links = mail_layout(4, 5, RING)
    assert_valid(centres, orientations, links)
    degree = np.bincount(links.ravel(), minlength=len(centres))
    interior = [i * 5 + j for i in (1, 2) for j in (1, 2, 3)]
    assert set(degree[interior]) == {4}  # 4-in-1: two neighbours above, two below
    # Tilt 45 degrees, alternating by row: axes of linked rings at 90 degrees (the paper's contact angle).
    axes = rotate(orientations, [0.0, 0.0, 1.0])
    np.testing.assert_allclose(np.sum(axes[links[:, 0]] * axes[links[:, 1]], axis=1), 0.0, atol=1e-15)


@pytest.mark.parametrize("aspect", [5.0, 6.0, 12.0])
def test_mail_valid_across_aspect_ratios(aspect):
    ring = Ring.from_aspect_ratio(aspect)
    centres, orientations, links = mail_layout(3, 4, ring)
    assert_valid(centres, orientations, links, ring)


def test_mail_of_thick_rings_is_refused():
    with pytest.raises(ValueError, match="too small for 4-in-1"):
        mail_geometry(Ring.from_aspect_ratio(3.5))
    with pytest.raises(ValueError, match="rings 0 and 5"):  # R = 4 r: the construction's diagonal pair overlaps
        mail_layout(3, 4, Ring.from_aspect_ratio(4.0))


def test_pam_block_nbo_net():
    centres, orientations, links = pam_layout(3, 3, 3, RING)
    assert len(centres) == 27 - 6  # parity classes (0,0,1) (4 sites) and (1,1,0) (2 sites) are empty
    assert_valid(centres, orientations, links)
    # The ring at the grid's centre, (1,1,1), has axis z and four linked neighbours in its plane (x and y).
    middle = int(np.flatnonzero(np.all(np.isclose(centres, RING.spacing), axis=1))[0])
    neighbours = links[np.any(links == middle, axis=1)].ravel()
    offsets = centres[neighbours[neighbours != middle]] - centres[middle]
    np.testing.assert_allclose(np.abs(offsets).sum(axis=0), [2 * RING.spacing, 2 * RING.spacing, 0.0])


def test_check_links_names_the_pair():
    centres, orientations, links = chain_layout(4, RING)
    with pytest.raises(ValueError, match="rings 1 and 2 are interlocked"):
        check_links(centres, orientations, RING, links[[0, 2]])
    moved = centres.copy()
    moved[3, 2] += 0.5 * RING.r  # ring 3 pulled through ring 2's wire
    with pytest.raises(ValueError, match="tubes of rings 2 and 3 overlap"):
        check_links(moved, orientations, RING, links)
    far = centres.copy()
    far[3, 2] += 10 * RING.R
    with pytest.raises(ValueError, match="rings 2 and 3 are listed as linked but are"):
        check_links(far, orientations, RING, links)


@pytest.mark.parametrize("law", ["hertz", "power-law"])
def test_hanging_chain_stretches_each_contact_by_the_weight_below(law):
    n = 6
    chain = Rings.chain(n, RING, law=law)
    rest = chain.equilibrium(force_tol=1e-9)
    K, exponent = (RING.K_c, 1.5) if law == "hertz" else RING.power_law()
    carried = np.arange(1, n) * RING.mass * STANDARD_GRAVITY  # contact k holds rings 0..k
    expected = (carried / K) ** (1 / exponent)
    approach = [-np.min(torus_contacts(rest.centres[k], rest.orientations[k], RING, rest.centres[k + 1],
                                       rest.orientations[k + 1], RING).gap) for k in range(n - 1)]  # fmt: skip
    # Residual force <= 1e-9 m g on a ring (the contact kernels' own floor is about 2e-10 m g): a relative
    # error <= 1e-9 m g / (n F) of each approach; the position rounding (1e-17 m) is far below the approaches.
    np.testing.assert_allclose(approach, expected, rtol=1e-8)
    # The chain stays straight (symmetry): a sideways offset x of the rings below a contact k draws the sideways
    # force (n - k) m g x / L (L the length of the chain, at most), so the residual 1e-9 m g bounds the offsets to
    # 1e-9 L (the solver's steps are those of the stiffness matrix, whose finite differences couple the sideways
    # swing to the stretch at their noise; measured 1.4e-12 m, about 1e-2 of the bound).
    length = float(np.ptp(chain.centres[:, 2]))
    np.testing.assert_allclose(rest.centres[:, :2], 0.0, atol=1e-9 * length)


def test_layouts_as_rings():
    chain = Rings.chain(4, RING, fixed_top=False)
    assert chain.links.tolist() == [[0, 1], [1, 2], [2, 3]] and not chain.fixed.any()
    mail = Rings.mail(3, 3, RING)
    assert sorted(map(tuple, mail.links.tolist())) == sorted(map(tuple, mail_layout(3, 3, RING)[2].tolist()))
    assert np.flatnonzero(mail.fixed).tolist() == [6, 7, 8]
    pam = Rings.pam(2, 2, 3, RING)
    assert len(pam.links) == len(pam_layout(2, 2, 3, RING)[2])


def test_netcdf_holds_the_inputs_and_reads_back(tmp_path):
    centres, orientations, links = chain_layout(3, RING)
    t = np.array([0.0, 1e-4])
    ds = rings_dataset(t, np.stack([centres, centres + 1e-3]), np.stack([orientations] * 2), RING, links,
                       fixed=[2], link_force=np.ones((2, 2)), attrs={"law": "hertz", "friction": 0.0})  # fmt: skip
    path = write_rings_netcdf(tmp_path / "run.nc", ds)
    back = read_rings_run(path)
    np.testing.assert_array_equal(back["centre"].values[1], centres + 1e-3)
    np.testing.assert_array_equal(back["R"].values, RING.R)
    assert back["fixed"].values.tolist() == [0, 0, 1] and back.attrs["law"] == "hertz"
    assert [p.name for p in tmp_path.iterdir()] == ["run.nc"]  # no temporary file left


def test_vtk_frames_are_tori_of_tube_radius_r(tmp_path):
    import meshio

    centres, orientations, _ = pam_layout(2, 2, 2, RING)
    t = np.array([0.0, 1e-3])
    pvd = write_rings_vtk(tmp_path, t, np.stack([centres, centres + 0.01]), np.stack([orientations] * 2), RING)
    assert pvd.read_text().count("<DataSet") == 2
    mesh = meshio.read(tmp_path / "rings_0001.vtu")
    owner = mesh.cell_data["ring"][0]
    triangles = mesh.cells_dict["triangle"]
    for k in range(len(centres)):
        points = mesh.points[np.unique(triangles[owner == k])]
        # Independent: distance of each vertex from the ring's centre circle (axis from the quaternion).
        axis = rotate(orientations[k], [0.0, 0.0, 1.0])
        d = points - (centres[k] + 0.01)
        h = d @ axis
        rho = np.linalg.norm(d - np.outer(h, axis), axis=1)
        np.testing.assert_allclose(np.hypot(h, rho - RING.R), RING.r, rtol=1e-12)  # rounding
    points, triangles = torus_mesh(RING.R, RING.r, 24, 10)
    assert triangles.shape == (480, 3) and triangles.max() == len(points) - 1
