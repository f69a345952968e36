"""(a) The slip velocity |V| in the x1–t plane as a grey scale (darker = faster), with the
slip front (first time |V| exceeds the threshold) as a dark line — the paper's Fig. 2a."""

import numpy as np

from .common import new_figure


def map_data(result):
    """The arrays the map draws: x1, time, |V| [n_samples, n_nodes] and the front."""
    known = np.isfinite(result.arrival_time)
    return {
        "x1": result.x1,
        "time": result.time,
        "abs_slip_velocity": np.abs(result.slip_velocity),
        "front_x1": result.front_x1[known],
        "front_time": result.arrival_time[known],
    }


def plot_map(result, probes=(6.0, 10.0), vmax=None, title=None):
    """Figure (a) of one run; `probes` draws vertical lines where figure (b) samples V."""
    data = map_data(result)
    fig, ax = new_figure(6.4, 4.8)
    v = data["abs_slip_velocity"] * 1e3  # mm/s
    mesh = ax.pcolormesh(data["x1"], data["time"], v, cmap="Greys", shading="nearest",
                         vmin=0.0, vmax=vmax * 1e3 if vmax else None, rasterized=True)
    fig.colorbar(mesh, ax=ax, label="|V| [mm/s]")
    if data["front_x1"].size:
        order = np.argsort(data["front_x1"])
        ax.plot(data["front_x1"][order], data["front_time"][order], color="black", lw=1.2,
                label="slip front")
        ax.legend(loc="upper left", fontsize="small")
    lo, hi = float(data["x1"].min()), float(data["x1"].max())
    for x in probes:
        if lo <= x <= hi:
            ax.axvline(x, color="tab:red", ls="--", lw=0.8)
    ax.set_xlabel("x1 [m]")
    ax.set_ylabel("t [s]")
    ax.set_title(title or f"Slip velocity, {result.label()}")
    return fig, data
