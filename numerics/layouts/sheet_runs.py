r"""What a sheet's run returns, its fields in NetCDF files, and maps of its link forces.

- :class:`SheetSimulation`, :class:`SheetBatch` -- a run (a batch) of a :class:`~ringchain.numerics.Sheet`:
  its network's run (``link_force`` time x links, ``displacement`` and ``velocity`` time x sites x 2,
  ``energy()``) with the sheet that made it; :meth:`SheetSimulation.to_dataset` and
  :meth:`SheetSimulation.to_netcdf` give its fields to xarray (self-describing NetCDF-4, SI units in the
  attributes), :func:`read_sheet_run` reads a file back;
- :func:`draw_link_forces` -- the links of a sheet as segments coloured by their forces;
  :func:`write_force_frames` -- such maps at several times, one PNG each (``ringchain sheet --plot``).
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from ringchain.theory import _validate as v

from ..engine._files import replacing, save_figure
from ..engine.results import NetworkSimulation

__all__ = [
    "SheetSimulation",
    "SheetBatch",
    "read_sheet_run",
    "sheet_run_options",
    "draw_link_forces",
    "write_force_frames",
]


@dataclass(frozen=True, eq=False)
class SheetSimulation(NetworkSimulation):
    """A run of a sheet: its network's run (``link_force``, ``displacement``, ``velocity``, ``energy()``).

    Attributes
    ----------
    sheet : Sheet
    impact_velocity : float or ndarray
        Speed of the struck sites at t = 0, m/s (the largest entry of the velocity field).
    drop_height : float, ndarray or None
        m, for a drop.
    """

    sheet: object = None
    impact_velocity: np.ndarray | float = 0.0
    drop_height: np.ndarray | float | None = None

    def to_dataset(self, every: int = 1):
        """The run as an :class:`xarray.Dataset`: fields on (time, site, component) and (time, link), SI units.

        ``every`` keeps every ``every``-th sample.  Coordinates: the sites' rest positions, rows and columns,
        the links' sites and families; attributes: the pattern, shape, loads and the integrator's report.
        """
        import xarray as xr

        if self.x.ndim != 2:
            raise ValueError("to_dataset takes one run: index a batch first (result[b])")
        every = v.count("every", every, 1)
        sheet, net = self.sheet, self.network
        sites = np.arange(net.n_sites) if self.sites is None else np.asarray(self.sites)
        links = self.links
        cut = slice(None, None, every)
        data = {
            "displacement": (("time", "site", "component"), self.displacement[cut],
                             {"units": "m", "long_name": "site displacement from the rest position"}),
            "velocity": (("time", "site", "component"), self.velocity[cut], {"units": "m/s"}),
            "link_force": (("time", "link"), self.link_force[cut],
                           {"units": "N", "long_name": "link force, positive in tension"}),
        }  # fmt: skip
        if self.sites is None:
            budget = self.energy()
            for name in ("kinetic", "contact", "gravity", "dissipated"):
                data[f"energy_{name}"] = (("time",), np.asarray(getattr(budget, name))[cut], {"units": "J"})
        coords = {
            "time": ("time", self.t[cut], {"units": "s"}),
            "site": ("site", sites),
            "component": ("component", ["x", "y"]),
            "link": ("link", links),
            "rest_position": (("site", "component"), net.positions[sites], {"units": "m"}),
            "link_i": ("link", net.i[links]),
            "link_j": ("link", net.j[links], {"long_name": "far site, -1 for a fixed point"}),
            "link_family": ("link", np.asarray(sheet.link_family)[links]),
        }
        if sheet.shape is not None:
            coords["row"], coords["col"] = ("site", sites // sheet.shape[1]), ("site", sites % sheet.shape[1])
        attrs = {"pattern": sheet.pattern or "links", "families": ", ".join(sheet.family_names),
                 "hanging": int(sheet.hanging), "boundary": sheet.boundary, "g_m_s2": float(self.g),
                 "impact_velocity_m_s": float(np.max(self.impact_velocity)),
                 "method": str(self.stats.get("method", "")), "created_by": "ringchain.numerics.Sheet"}  # fmt: skip
        if sheet.shape is not None:
            attrs["rows"], attrs["cols"] = sheet.shape
        if sheet.pretension is not None:
            attrs["pretension_N"] = np.asarray(sheet.pretension, dtype=float)
        if self.drop_height is not None:
            attrs["drop_height_m"] = float(np.max(self.drop_height))
        data.update(_network_variables(sheet, net))
        attrs.update(_inputs(sheet, self.stats))
        return xr.Dataset(data, coords=coords, attrs=attrs)

    def to_netcdf(self, path, every: int = 1) -> None:
        """Write :meth:`to_dataset` to a NetCDF file (NetCDF-4 through h5netcdf; read it with
        :func:`read_sheet_run` or ``xarray.open_dataset``)."""
        dataset = self.to_dataset(every)
        with replacing(path) as tmp:  # whole or not at all: an interrupt leaves the previous file
            dataset.to_netcdf(tmp, engine="h5netcdf")


@dataclass(frozen=True, eq=False)
class SheetBatch(SheetSimulation):
    """B runs of one sheet: arrays of shape (B, T, ...); ``result[b]`` is run b as a :class:`SheetSimulation`."""

    def __len__(self) -> int:
        return self.x.shape[0]

    def __getitem__(self, b) -> SheetSimulation:
        b = range(len(self))[b]
        return SheetSimulation(
            t=self.t, x=self.x[b], u=self.u[b], dissipated=self.dissipated[b], g=self.g, network=self.network,
            stats=self.stats, sites=self.sites, sheet=self.sheet, impact_velocity=float(self.impact_velocity[b]),
            drop_height=None if self.drop_height is None else float(self.drop_height[b]),
        )  # fmt: skip


def _network_variables(sheet, net) -> dict:
    """Every input of the sheet's network, on dimensions of its own (all sites, all links), SI units.

    With these, :meth:`~ringchain.numerics.Sheet.from_run` rebuilds the very network that ran, whatever
    part of it the run recorded.
    """
    both, one = ("network_site", "component"), ("network_link",)
    links = ("network_link", "component")
    return {
        "site_mass": (("network_site",), np.broadcast_to(net.mass, (net.n_sites,)),
                      {"units": "kg", "long_name": "inertial mass of each ring (m_eff)"}),
        "site_weight_mass": (("network_site",), np.broadcast_to(net.weight_mass, (net.n_sites,)),
                             {"units": "kg", "long_name": "mass gravity acts on (m0 hanging, 0 lying flat)"}),
        "site_position": (both, net.positions, {"units": "m", "long_name": "rest position of every ring centre"}),
        "impact_field": (both, sheet.impact_field, {"units": "1", "long_name": "velocity per unit impact speed"}),
        "network_link_i": (one, net.i),
        "network_link_j": (one, net.j, {"long_name": "far site, -1 for a fixed point"}),
        "network_link_family": (one, np.asarray(sheet.link_family)),
        "link_K": (one, np.broadcast_to(sheet.K, (net.n_links,)), {"units": "N/m^n", "long_name": "Eq. (4) K"}),
        "link_n": (one, np.broadcast_to(sheet.n, (net.n_links,)), {"units": "1", "long_name": "Eq. (4) n"}),
        "link_gamma": (one, np.broadcast_to(sheet.gamma, (net.n_links,)), {"units": "N s/m"}),
        "link_angle": (one, np.broadcast_to(sheet.link_angle, (net.n_links,)),
                       {"units": "rad", "long_name": "angle between the planes of the two rings"}),
        "link_prestretch": (one, net.prestretch, {"units": "m"}),
        "link_static_tension": (one, sheet.static_tension(0.0) if not sheet.hanging else np.zeros(net.n_links),
                                {"units": "N", "long_name": "pretension of each link (0 for a hanging sheet)"}),
        "link_anchor": (links, net.anchor_positions, {"units": "m", "long_name": "fixed point of anchored links"}),
        "link_shift": (links, net.shifts, {"units": "m", "long_name": "periodic image offset of the far site"}),
    }  # fmt: skip


def _inputs(sheet, stats) -> dict:
    """The sheet's other inputs and the integrator's settings, as NetCDF attributes (SI units in the names)."""
    attrs = {"m_eff_ratio": float(sheet.m_eff_ratio), "gamma_N_s_m": float(sheet.gamma),
             "struck_sites": np.asarray(sheet.struck_sites, dtype=np.int64),
             "support_links": np.asarray(sheet.support_links, dtype=np.int64)}  # fmt: skip
    for name in EDGE_NAMES:
        attrs[f"edge_{name}"] = np.asarray(sheet.edge(name), dtype=np.int64)
    if sheet.ring is not None:
        ring = sheet.ring
        mat = ring.material
        attrs.update(R_m=float(ring.R), r_m=float(ring.r), material=str(mat.name), E_Pa=float(mat.E), nu=float(mat.nu),
                     rho_kg_m3=float(mat.rho), ring_angle_rad=float(ring.angle), thin=int(ring.thin))  # fmt: skip
    for key in ("rtol", "atol", "dt"):
        if stats.get(key) is not None:
            attrs[key] = float(stats[key])
    return attrs


#: The edges of a sheet (the order of :data:`ringchain.numerics.layouts.sheet.EDGES`).
EDGE_NAMES = ("bottom", "top", "left", "right")

#: What every file of :meth:`SheetSimulation.to_netcdf` holds; a file without one of them is refused.
_REQUIRED = ("displacement", "velocity", "link_force", "link_K", "link_n", "site_mass", "impact_field")


def read_sheet_run(path):
    """A sheet's run written by :meth:`SheetSimulation.to_netcdf`, as an :class:`xarray.Dataset` (loaded).

    Raises
    ------
    DataError
        (a ValueError) naming the file, if it is not a NetCDF-4 file, was not written by
        :meth:`SheetSimulation.to_netcdf`, or lacks a field or an input the run wrote (an incomplete file).
    """
    import xarray as xr

    from ..engine.traces import DataError

    try:
        dataset = xr.load_dataset(path, engine="h5netcdf")
    except (OSError, ValueError, KeyError, TypeError) as exc:  # h5py's OSError does not name the file
        raise DataError(f"not a sheet's run: it cannot be read as a NetCDF-4 file ({' '.join(str(exc).split())})",
                        path=path) from None  # fmt: skip
    if dataset.attrs.get("created_by") not in ("ringchain.numerics.Sheet", "ringchain.numerics.sheet"):  # new, 0.1
        raise DataError("not a sheet's run written by ringchain (SheetSimulation.to_netcdf): no created_by", path=path)
    missing = [name for name in _REQUIRED if name not in dataset]
    if "site" in dataset.dims and dataset.sizes["site"] == dataset.sizes.get("network_site"):
        missing += [f"energy_{k}" for k in ("kinetic", "contact", "gravity", "dissipated") if f"energy_{k}" not in
                    dataset]  # fmt: skip
    if missing:
        raise DataError(f"an incomplete sheet's run: {', '.join(missing)} missing (write it again)", path=path)
    for name in ("displacement", "velocity", "link_force"):
        if dataset[name].size and not np.isfinite(dataset[name].values).any():
            raise DataError(f"an incomplete sheet's run: {name} holds no number (write it again)", path=path)
    return dataset


def draw_link_forces(ax, sheet, forces, *, norm=None, cmap="magma", linewidth=2.0, links=None):
    """Draw every link of ``sheet`` as a segment between its ring centres, coloured by its force (N).

    Parameters
    ----------
    ax : matplotlib Axes
    sheet : Sheet
    forces : array_like, shape (n_links,) or (len(links),)
        Force of each link drawn, N.
    norm : matplotlib Normalize, optional
        Colour scale (default: 0 to the largest force).
    cmap, linewidth
        Colour map and line width (points).
    links : array_like of int, optional
        The links drawn (default all; links to fixed points are drawn to them).

    Returns
    -------
    matplotlib.collections.LineCollection
        For a colour bar.
    """
    from matplotlib.collections import LineCollection
    from matplotlib.colors import Normalize

    net = sheet.network()
    links = np.arange(net.n_links) if links is None else np.asarray(links)
    forces = np.asarray(forces, dtype=float)
    start = net.positions[net.i[links]]
    segments = np.stack([start, start + net.rest_vectors[links]], axis=1)
    norm = Normalize(0.0, max(float(forces.max()), 1e-300)) if norm is None else norm
    lines = LineCollection(segments, cmap=cmap, norm=norm, linewidths=linewidth, capstyle="round")
    lines.set_array(forces)
    ax.add_collection(lines)
    ax.set_aspect("equal")
    ax.autoscale_view()
    return lines


def write_force_frames(run: SheetSimulation, folder, count: int = 6, *, dpi: int = 110) -> list:
    """Maps of the link forces of one run at ``count`` evenly spaced times, one PNG each, into ``folder``.

    One colour scale (0 to the largest force of the run) for every frame.  Returns the paths written
    (``frame_000.png``, ...); the folder is created if needed, and frames of an earlier run beyond ``count``
    (``frame_NNN.png``) are removed, so that the folder holds this run's maps only.
    """
    from matplotlib.colors import Normalize

    from ..engine.plots import new_figure

    count = v.count("count", count, 1)
    if run.x.ndim != 2:
        raise ValueError("write_force_frames takes one run: index a batch first (result[b])")
    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    forces = run.link_force
    norm = Normalize(0.0, max(float(forces.max()), 1e-300))
    paths = []
    for k, index in enumerate(np.linspace(0, run.t.size - 1, count).round().astype(int)):
        fig = new_figure(figsize=(5.2, 4.4))
        ax = fig.add_subplot()
        lines = draw_link_forces(ax, run.sheet, forces[index], norm=norm, links=run.links, linewidth=1.2)
        fig.colorbar(lines, ax=ax, label="link force (N)")
        ax.set(title=f"t = {run.t[index] * 1e3:.3g} ms", xlabel="x (m)", ylabel="y (m)")
        path = folder / f"frame_{k:03d}.png"
        save_figure(fig, path, dpi=dpi)
        paths.append(path)
    for stale in folder.glob("frame_*.png"):  # frames of an earlier, longer run: not of this one
        if re.fullmatch(r"frame_\d{3,}\.png", stale.name) and stale not in paths:
            stale.unlink()
    return paths


def sheet_run_options(run) -> dict:
    """The arguments of :func:`~ringchain.numerics.simulate` that made a sheet's run, from its file.

    Parameters
    ----------
    run : xarray.Dataset or str or path
        What :func:`read_sheet_run` returns, or the file.

    Returns
    -------
    dict
        ``t_end`` (s), ``t_eval`` (s, the samples the file kept), ``impact_velocity`` (m/s) or ``drop_height``
        (m), ``gravity``, ``g`` (m/s^2), ``method`` and its ``rtol`` and ``atol`` (adaptive) or ``dt`` (s, Verlet):
        ``simulate(Sheet.from_run(run), **sheet_run_options(run))`` runs it again to the same numbers.
    """
    dataset = run if hasattr(run, "attrs") else read_sheet_run(run)
    attrs = dataset.attrs
    t = np.asarray(dataset["time"].values, dtype=float)
    options = {"t_end": float(t[-1]), "t_eval": t, "method": str(attrs["method"]) or None}
    if options["method"] is None:
        del options["method"]
    g = float(attrs["g_m_s2"])
    options.update(gravity=g > 0, **({"g": g} if g > 0 else {}))
    if "drop_height_m" in attrs:
        options["drop_height"] = float(attrs["drop_height_m"])
    else:
        options["impact_velocity"] = float(attrs["impact_velocity_m_s"])
    keys = ("dt",) if options.get("method") == "verlet" else ("rtol", "atol")
    options.update({key: float(attrs[key]) for key in keys if key in attrs})
    return options
