r"""Files of a network of rigid rings: NetCDF (the complete record) and VTK (to look at in ParaView).

- :func:`rings_dataset` -- a run's fields as an :class:`xarray.Dataset`: centres and orientations
  (time x ring x 3 or 4), velocities, angular velocities and link forces when given, and every input
  needed to build the network again (each ring's R, r and material, the links, the fixed rings, the law,
  friction and gravity as attributes); :func:`write_rings_netcdf` writes it (NetCDF-4 through h5netcdf,
  to a temporary name renamed into place when complete) and :func:`read_rings_run` reads it back;
- :func:`torus_mesh` -- the triangulated surface of a torus in its body frame;
- :func:`write_rings_vtk` -- one ``.vtu`` file per frame, every ring a meshed torus, with a ``.pvd``
  collection of the frames and their times (ParaView opens the ``.pvd`` as a time series).
"""

from __future__ import annotations

import os
import secrets
from pathlib import Path

import numpy as np
from ringchain.theory import _validate as v

from .rings_layouts import ring_radii, rotate

__all__ = ["rings_dataset", "write_rings_netcdf", "read_rings_run", "torus_mesh", "write_rings_vtk"]


def _frames(name, array, n, width):
    array = v.as_float(name, array)
    if array.ndim == 2:
        array = array[None]
    if array.ndim != 3 or array.shape[1:] != (n, width):
        raise ValueError(f"{name} must have shape (time, {n}, {width}), got {array.shape}")
    return array


def rings_dataset(t, centres, orientations, rings, links, *, fixed=(), velocities=None, angular_velocities=None,
                  link_force=None, attrs=None):  # fmt: skip
    """A run of a network of rigid rings as an :class:`xarray.Dataset` (SI units in the attributes).

    Parameters
    ----------
    t : array_like, shape (T,)
        Times, s.
    centres : array_like, shape (T, n, 3)
        Ring centres, m.
    orientations : array_like, shape (T, n, 4)
        Unit quaternions (w, x, y, z), body -> space.
    rings : Ring or sequence of Ring
        The rings' geometry and material (one for all, or one per ring).
    links : array_like, shape (n_links, 2)
        The interlocked pairs.
    fixed : sequence of int
        The fixed rings (anchors).
    velocities : array_like, shape (T, n, 3), optional
        m/s, in space.
    angular_velocities : array_like, shape (T, n, 3), optional
        rad/s, in each ring's body frame.
    link_force : array_like, shape (T, n_links), optional
        N, tension positive.
    attrs : dict, optional
        The run's other inputs (law, friction, gravity, impact, method...), stored as attributes; values
        must be numbers or strings.
    """
    import xarray as xr
    from ringchain.theory import Ring

    t = v.as_float("t", t).reshape(-1)
    centres = _frames("centres", centres, np.shape(centres)[-2], 3)
    n = centres.shape[1]
    orientations = _frames("orientations", orientations, n, 4)
    if not (centres.shape[0] == orientations.shape[0] == t.size):
        raise ValueError(f"t, centres and orientations need one entry per time, got {t.size}, {centres.shape[0]} "
                         f"and {orientations.shape[0]}")  # fmt: skip
    R, r = ring_radii(rings, n)
    per_ring = [rings] * n if isinstance(rings, Ring) else list(rings)
    links = np.asarray(links, dtype=np.intp).reshape(-1, 2)
    is_fixed = np.zeros(n, dtype=np.int8)
    is_fixed[np.asarray(fixed, dtype=np.intp)] = 1
    data = {
        "centre": (("time", "ring", "axis"), centres, {"units": "m", "long_name": "ring centre"}),
        "orientation": (("time", "ring", "quaternion"), orientations,
                        {"long_name": "unit quaternion (w, x, y, z), body to space; ring axis = body z"}),
    }  # fmt: skip
    if velocities is not None:
        data["velocity"] = (("time", "ring", "axis"), _frames("velocities", velocities, n, 3), {"units": "m/s"})
    if angular_velocities is not None:
        data["angular_velocity"] = (("time", "ring", "axis"), _frames("angular_velocities", angular_velocities, n, 3),
                                    {"units": "rad/s", "long_name": "angular velocity in the body frame"})  # fmt: skip
    if link_force is not None:
        force = v.as_float("link_force", link_force).reshape(t.size, -1)
        if force.shape[1] != len(links):
            raise ValueError(f"link_force must have one column per link ({len(links)}), got {force.shape[1]}")
        data["link_force"] = (("time", "link"), force, {"units": "N", "long_name": "link force, tension positive"})
    coords = {
        "time": ("time", t, {"units": "s"}),
        "axis": ("axis", ["x", "y", "z"]),
        "quaternion": ("quaternion", ["w", "x", "y", "z"]),
        "R": ("ring", R, {"units": "m", "long_name": "major (centre-circle) radius"}),
        "r": ("ring", r, {"units": "m", "long_name": "tube radius"}),
        "E": ("ring", [ring.material.E for ring in per_ring], {"units": "Pa"}),
        "nu": ("ring", [ring.material.nu for ring in per_ring], {"units": "1"}),
        "rho": ("ring", [ring.material.rho for ring in per_ring], {"units": "kg/m3"}),
        "material": ("ring", [ring.material.name for ring in per_ring]),
        "fixed": ("ring", is_fixed, {"long_name": "1 for a fixed ring (anchor)"}),
        "link_i": ("link", links[:, 0]),
        "link_j": ("link", links[:, 1]),
    }
    attrs = {"created_by": "ringchain.numerics.layouts.rings", **(attrs or {})}
    for key, value in attrs.items():
        if not isinstance(value, (int, float, str, np.integer, np.floating)):
            raise TypeError(f"attribute {key} must be a number or a string, got {type(value).__name__}")
    return xr.Dataset(data, coords=coords, attrs=attrs)


def write_rings_netcdf(path, dataset) -> Path:
    """Write ``dataset`` (:func:`rings_dataset`) to ``path``: to a temporary name first, renamed when complete.

    A reader never sees half a file, and an interrupted write leaves any earlier file at ``path`` as it
    was.  Returns the path written.
    """
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}-{secrets.token_hex(4)}.tmp")
    try:
        dataset.to_netcdf(tmp, engine="h5netcdf")
        os.replace(tmp, path)
    finally:
        tmp.unlink(missing_ok=True)
    return path


def read_rings_run(path):
    """A run written by :func:`write_rings_netcdf`, as an :class:`xarray.Dataset` (loaded into memory)."""
    import xarray as xr

    return xr.load_dataset(path, engine="h5netcdf")


def torus_mesh(R: float, r: float, n_major: int = 24, n_minor: int = 10):
    """Triangulated torus in its body frame: centre circle of radius R (m) in the xy plane, tube radius r (m).

    Returns ``(points, triangles)``: vertices (n_major * n_minor, 3) on the tube surface, at distance r
    from the centre circle, and triangles (2 n_major n_minor, 3) of vertex indices, outward facing.
    """
    R, r = float(v.positive("R", R, "m")), float(v.positive("r", r, "m"))
    n_major, n_minor = v.count("n_major", n_major, 3), v.count("n_minor", n_minor, 3)
    phi = 2 * np.pi * np.arange(n_major) / n_major
    psi = 2 * np.pi * np.arange(n_minor) / n_minor
    P, S = np.meshgrid(phi, psi, indexing="ij")
    rho = R + r * np.cos(S)
    points = np.stack([rho * np.cos(P), rho * np.sin(P), r * np.sin(S)], axis=-1).reshape(-1, 3)
    a, b = np.meshgrid(np.arange(n_major), np.arange(n_minor), indexing="ij")
    a1, b1 = (a + 1) % n_major, (b + 1) % n_minor
    k00, k10, k01, k11 = a * n_minor + b, a1 * n_minor + b, a * n_minor + b1, a1 * n_minor + b1
    triangles = np.concatenate(
        [np.stack([k00, k10, k11], -1).reshape(-1, 3), np.stack([k00, k11, k01], -1).reshape(-1, 3)]
    )
    return points, triangles


def write_rings_vtk(folder, t, centres, orientations, rings, *, ring_data=None, n_major=24, n_minor=10,
                    name="rings") -> Path:  # fmt: skip
    """Write every frame as a ``.vtu`` of meshed tori, and a ``.pvd`` listing them with their times.

    Parameters
    ----------
    folder : str or Path
        Created if needed; receives ``{name}_0000.vtu``, ... and ``{name}.pvd``.
    t : array_like, shape (T,)
        Times, s.
    centres, orientations : array_like, shapes (T, n, 3) and (T, n, 4)
        m; unit quaternions (w, x, y, z), body -> space.
    rings : Ring or sequence of Ring
        Geometry of each ring (R, r in m).
    ring_data : dict of name -> array (T, n), optional
        Values per ring and frame, written as cell data on every triangle of that ring (e.g. speed).
    n_major, n_minor : int
        Vertices around the centre circle and around the tube.
    name : str
        Stem of the files.

    Returns
    -------
    Path
        The ``.pvd`` file.  The cell data ``ring`` numbers the ring of each triangle.
    """
    import meshio

    t = v.as_float("t", t).reshape(-1)
    centres = _frames("centres", centres, np.shape(centres)[-2], 3)
    n = centres.shape[1]
    orientations = _frames("orientations", orientations, n, 4)
    R, r = ring_radii(rings, n)
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    body, faces = [], []
    for k in range(n):
        points, triangles = torus_mesh(R[k], r[k], n_major, n_minor)
        body.append(points)
        faces.append(triangles + k * len(points))
    body, faces = np.stack(body), np.concatenate(faces)
    per_vertex = body.shape[1]
    owner = np.repeat(np.arange(n), 2 * per_vertex)
    entries = []
    for frame in range(t.size):
        points = rotate(orientations[frame][:, None, :], body) + centres[frame][:, None, :]
        cell_data = {"ring": [owner]}
        for key, values in (ring_data or {}).items():
            cell_data[key] = [np.asarray(values, dtype=float)[frame][owner]]
        file = folder / f"{name}_{frame:04d}.vtu"
        meshio.write(file, meshio.Mesh(points.reshape(-1, 3), [("triangle", faces)], cell_data=cell_data))
        entries.append(f'    <DataSet timestep="{float(t[frame])!r}" group="" part="0" file="{file.name}"/>')
    pvd = folder / f"{name}.pvd"
    pvd.write_text('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n  <Collection>\n'
                   + "\n".join(entries) + "\n  </Collection>\n</VTKFile>\n")  # fmt: skip
    return pvd
