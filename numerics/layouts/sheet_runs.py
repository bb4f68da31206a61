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

from dataclasses import dataclass
from pathlib import Path

import numpy as np
from ringchain.theory import _validate as v

from ..engine.results import NetworkSimulation

__all__ = ["SheetSimulation", "SheetBatch", "read_sheet_run", "draw_link_forces", "write_force_frames"]


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
        return xr.Dataset(data, coords=coords, attrs=attrs)

    def to_netcdf(self, path, every: int = 1) -> None:
        """Write :meth:`to_dataset` to a NetCDF file (NetCDF-4 through h5netcdf; read it with
        :func:`read_sheet_run` or ``xarray.open_dataset``)."""
        self.to_dataset(every).to_netcdf(path, engine="h5netcdf")


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


def read_sheet_run(path):
    """A sheet's run written by :meth:`SheetSimulation.to_netcdf`, as an :class:`xarray.Dataset` (loaded)."""
    import xarray as xr

    return xr.load_dataset(path, engine="h5netcdf")


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
    (``frame_000.png``, ...); the folder is created if needed.
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
        fig.savefig(path, dpi=dpi)
        paths.append(path)
    return paths
