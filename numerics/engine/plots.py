"""Figures of runs and fits, drawn by Matplotlib's Agg canvas (no pyplot, no display needed).

- :func:`new_figure` -- a Figure with fixed margins (one draw per figure keeps the commands quick);
- :func:`plot_sensor_traces` -- the sensor traces of a chain's run, as ``ringchain simulate --plot`` draws them.
"""

from __future__ import annotations

__all__ = ["new_figure", "plot_sensor_traces"]


def new_figure(**kwargs):
    """A matplotlib Figure drawn by the Agg canvas (no pyplot, no display needed).

    Fixed margins rather than a layout engine: one draw per figure, which keeps
    ``ringchain paper`` quick.
    """
    from matplotlib.figure import Figure

    fig = Figure(layout=None, **kwargs)  # explicit: a user's rcParams may turn a layout engine on
    fig.subplots_adjust(left=0.15, right=0.97, bottom=0.14, top=0.9, wspace=0.08)
    return fig


def plot_sensor_traces(path, sim, sensors, title: str) -> None:
    """Write the sensor forces (N) of ``sensors`` (rings) of the chain run ``sim`` against time to ``path``."""
    fig = new_figure(figsize=(6, 3.6))
    ax = fig.add_subplot()
    for k in sensors:
        ax.plot(sim.t * 1e3, sim.sensor(k), label=f"ring {k}")
    ax.set(xlabel="time after impact (ms)", ylabel="sensor force (N)", title=title)
    ax.legend()
    fig.savefig(path, dpi=120)
