"""(f) The speed–accuracy chart: relative error against wall time (and, when the rows have
`memory_bytes`, against memory in a second panel), one curve per L and method: colour = L,
marker and line style = method (FE ● solid, spectral BI ■ dashed), each point labelled with
its n_d. Input rows: {L, n_d, wall_time_s, error[, method, memory_bytes]} (error > 0; rows
without a positive error, such as a reference run, are left out; `method` defaults to "fe").

One definition of the error everywhere (the server's GET /studies/{id}/speed-accuracy and
every client path): the larger of the relative differences of `propagation_distance` and
`arrival_time_at_probe` from a reference run of the same L — the finest run of an L that has
a converged run (`reference="converged"`, the server's), the finest run of each L when the
client computes the errors from runs (`"finest"`), or, for a study where no L converged, the
finest run of each L, labelled as such (`"unconverged"`). The figure states which.
"""

import math

from matplotlib.lines import Line2D
from matplotlib.ticker import FuncFormatter, LogLocator, MaxNLocator, NullFormatter

from .. import methods as methods_mod
from ..errors import UsageError
from .common import colours, new_figure

OTHER = {"marker": "^", "linestyle": ":", "open": False, "offset": (4, 3)}  # a method not listed


def style_of(m):
    """Marker, line style, open marker, point-label offset and legend label of a method
    (methods.STYLES: FE filled circles on solid lines, BI open squares on dashed ones)."""
    s = methods_mod.style(m)
    if s is None:
        return {**OTHER, "label": m}
    return {"marker": s["marker"], "linestyle": s["ls"], "open": s["open"], "offset": s["offset"],
            "label": f"{methods_mod.label(m)} ({methods_mod.title(m)})"}


def _positive(value):
    try:
        return float(value) > 0 and math.isfinite(float(value))
    except (TypeError, ValueError):
        return False


def usable(row):
    try:
        return _positive(row["error"]) and _positive(row["wall_time_s"])
    except KeyError:
        return False


def length_label(L):
    """1e-4 -> "1e-4 m", 5e-05 -> "5e-5 m", 0.5 -> "0.5 m"."""
    if L <= 0 or 1e-2 <= L < 1e3:
        return f"{L:g} m"
    mantissa, exponent = f"{L:.3e}".split("e")
    return f"{float(mantissa):g}e{int(exponent)} m"


def readable_log_axis(axis, values):
    """Tick labels a reader can use on a log axis: plain numbers ("0.02", "1e-05"), ticks at
    1, 2, 5 per decade over a few decades, at decades only over many, denser within a
    decade, evenly spaced values over a narrow range (where log ticks would leave none)."""
    values = [v for v in values if v > 0]
    if not values:
        return
    span = math.log10(max(values) / min(values))
    if span < 0.3:
        axis.set_major_locator(MaxNLocator(nbins=4))
    elif span < 1:
        axis.set_major_locator(LogLocator(base=10, subs=(1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 8.0)))
    else:
        axis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 5.0) if span <= 2.5 else (1.0,)))
    axis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:.0f}" if 1 <= v < 1e6 and v == round(v)
                                           else f"{v:.3g}"))
    axis.set_minor_formatter(NullFormatter())


def method(row):
    return row.get("method") or methods_mod.default()


ERROR_DEFINITION = ("error = max(|d - d_ref| / d_ref, |t - t_ref| / t_ref);  "
                    "d: propagation_distance, t: arrival_time_at_probe")
REFERENCES = {
    "converged": "reference: the finest run of each L that has a converged run",
    "finest": "reference: the finest run of each L (its convergence not checked)",
    "unconverged": "reference: the finest run of each L. No L of the study converged:\n"
                   "these are differences from the finest run, not errors against a converged run",
}


def plot_cost(rows, title=None, reference="converged"):
    rows = [r for r in rows if usable(r)]
    if not rows:
        raise UsageError("cost chart: no rows with a positive error and wall_time_s")
    groups = {}
    for r in rows:
        groups.setdefault((method(r), float(r["L"])), []).append(r)
    lengths = sorted({L for _, L in groups}, reverse=True)
    methods = sorted({m for m, _ in groups}, key=lambda m: (not methods_mod.known(m), m))
    colour_of = dict(zip(lengths, colours(len(lengths))))
    panels = [("wall_time_s", 1.0, "wall time [s]")]
    if any(_positive(r.get("memory_bytes")) for r in rows):
        panels.append(("memory_bytes", 1e6, "memory estimate [MB]"))
    fig, axes = new_figure(width=5.2 * len(panels) + 2.4, height=4.4, ncols=len(panels))
    data = {}
    for ax, (key, scale, xlabel) in zip(axes, panels):
        for (m, L), runs in sorted(groups.items(), key=lambda kv: (kv[0][0], -kv[0][1])):
            runs = sorted((r for r in runs if _positive(r.get(key))), key=lambda r: float(r["n_d"]))
            if not runs:
                continue
            x = [float(r[key]) / scale for r in runs]
            err = [float(r["error"]) for r in runs]
            style = style_of(m)
            ax.plot(x, err, marker=style["marker"], linestyle=style["linestyle"],
                    color=colour_of[L], markersize=5, linewidth=1.2,
                    markerfacecolor="none" if style["open"] else colour_of[L])
            entry = data.setdefault((m, L), {"n_d": [float(r["n_d"]) for r in runs], "error": err})
            entry[key] = [float(r[key]) for r in runs]
            for r, xi, e in zip(runs, x, err):
                ax.annotate(f"{float(r['n_d']):g}", (xi, e), textcoords="offset points",
                            xytext=style["offset"], fontsize="x-small",
                            color=colour_of[L])
        ax.set_xscale("log")
        ax.margins(x=0.08, y=0.12)  # markers and their n_d labels inside the frame
        ax.set_yscale("log")
        drawn = [v for (m, L), d in data.items() if key in d for v in d[key]]
        readable_log_axis(ax.xaxis, [v / scale for v in drawn])
        readable_log_axis(ax.yaxis, [v for d in data.values() if key in d for v in d["error"]])
        ax.set_xlabel(xlabel)
        ax.set_ylabel("relative error")
        ax.grid(True, which="major", alpha=0.3)
    handles = [Line2D([], [], color=colour_of[L], linewidth=3, label=f"L = {length_label(L)}") for L in lengths]
    handles += [Line2D([], [], color="0.3", marker=style_of(m)["marker"],
                       linestyle=style_of(m)["linestyle"],
                       markerfacecolor="none" if style_of(m)["open"] else "0.3",
                       label=style_of(m)["label"]) for m in methods]
    axes[-1].legend(handles=handles, loc="upper left", bbox_to_anchor=(1.02, 1.0),
                    fontsize="small", borderaxespad=0.0)
    if reference not in REFERENCES:
        raise UsageError(f"cost chart: reference {reference!r}: choose from {', '.join(REFERENCES)}")
    fig.suptitle(title or "Speed and accuracy (point labels: n_d)")
    fig.supxlabel(f"{ERROR_DEFINITION}\n{REFERENCES[reference]}", fontsize="small", color="0.25")
    return fig, data
