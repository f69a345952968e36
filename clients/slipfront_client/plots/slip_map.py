"""(a) The slip velocity |V| in the x1–t plane (darker = faster), with the slip front (first
time |V| exceeds the threshold) as a dark line, the stations' rupture times, and the positions
of figure (b) — by default the run's own stations, else its probes — the paper's Fig. 2a. The
axes show the event (where and when |V| exceeded 1 % of its peak, and the front), unless
`whole=True` asks for the whole domain and run.

The colour scale must show the whole pulse, its tip and tail as well as its peak: by default
it is logarithmic over four decades below the largest |V| (`scale="log"`); `scale="linear"`
clips at the 90th percentile of the slipping nodes' |V| (the rare peak values are shown as
the darkest colour and the colour bar says so) unless `vmax` is given.
"""

import numpy as np
from matplotlib.colors import LogNorm, Normalize

from ..errors import UsageError
from .common import new_figure

SCALES = ("log", "linear")
LOG_DECADES = 4
CLIP_PERCENTILE = 90  # linear scale: the top of the scale, percentile of the slipping |V|


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


def colour_norm(v, scale, vmax=None):
    """(norm, clipped): the colour normalisation of |V| values `v` (any units) and whether
    values above its top are clipped."""
    finite = v[np.isfinite(v)]
    peak = float(finite.max()) if finite.size else 1.0
    peak = peak if peak > 0 else 1.0
    if scale == "log":
        top = vmax or peak
        return LogNorm(vmin=top * 10.0 ** -LOG_DECADES, vmax=top, clip=True), top < peak
    if scale == "linear":
        if vmax:
            top = vmax
        else:
            moving = finite[finite > peak * 1e-3]
            top = float(np.percentile(moving, CLIP_PERCENTILE)) if moving.size else peak
        return Normalize(vmin=0.0, vmax=top, clip=True), top < peak
    raise UsageError(f"colour scale {scale!r}: choose from {', '.join(SCALES)}")


def plot_map(result, probes=None, vmax=None, title=None, scale="log", whole=False):
    """Figure (a) of one run; `probes` draws vertical lines where figure (b) samples V (None:
    the run's own stations or probes, Result.positions). `scale`: "log" (default) or "linear"
    (clipped); `vmax` [m/s] sets the top of the scale; `whole`: the whole domain and run
    instead of the event."""
    data = map_data(result)
    fig, ax = new_figure(6.4, 4.8)
    v = data["abs_slip_velocity"] * 1e3  # mm/s
    norm, clipped = colour_norm(v, scale, vmax * 1e3 if vmax else None)
    shown = np.where(v > 0, v, np.nan) if scale == "log" else v
    cmap = "Greys"
    mesh = ax.pcolormesh(data["x1"], data["time"], shown, cmap=cmap, norm=norm,
                         shading="nearest", rasterized=True)
    label = "|V| [mm/s]" + (" (log scale)" if scale == "log" else "")
    if clipped:
        label += ", clipped at top"
    bar = fig.colorbar(mesh, ax=ax, label=label, extend="max" if clipped else "neither")
    if scale == "log":
        bar.ax.set_facecolor("white")  # |V| below the scale's bottom: no slip
    data.update(scale=scale, vmin=float(norm.vmin), vmax=float(norm.vmax), clipped=clipped)
    front_threshold, station_threshold = result.thresholds()
    if data["front_x1"].size:
        order = np.argsort(data["front_x1"])
        ax.plot(data["front_x1"][order], data["front_time"][order], color="tab:orange", lw=1.4,
                label=f"slip front (|V| > {front_threshold:.3g} m/s)")
    ruptures = [(s["x1"], s["rupture_time"]) for s in result.metrics.get("stations") or []
                if s.get("rupture_time") is not None]
    if ruptures:
        same = station_threshold == front_threshold
        ax.plot(*zip(*ruptures), ls="none", marker="D", ms=5, mfc="white", mec="tab:orange",
                label=f"station rupture times (|V| > {station_threshold:.3g} m/s"
                      + (", as the front)" if same else ")"))
    lo, hi = float(data["x1"].min()), float(data["x1"].max())
    watched = result.positions() if probes is None else [(float(x), "") for x in probes]
    drawn = []
    for (x, what), style in zip(watched, ["--", ":", "-.", (0, (5, 2, 1, 2))]):
        if lo <= x <= hi:
            ax.axvline(x, color="tab:red", ls=style, lw=1.0,
                       label=f"x1 = {x:g} m ({what})" if what else f"probe x1 = {x:g} m")
            drawn.append(x)
    data["probes"] = drawn
    window = None if whole else result.event_window()
    if window:
        ax.set_xlim(*window[0])
        ax.set_ylim(*window[1])
    data["window"] = window
    if ax.get_legend_handles_labels()[0]:
        ax.legend(loc="upper left", fontsize="small", framealpha=0.9)
    ax.set_xlabel("x1 [m]" + ("" if window is None else
                              "  (zoomed to the event; the whole box: plot map --whole)"))
    ax.set_ylabel("t [s]")
    ax.set_title(title or f"Slip velocity, {result.label()}", fontsize="medium")
    return fig, data
