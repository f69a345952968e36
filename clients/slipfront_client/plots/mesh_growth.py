"""A quantity against the mesh density on log-log axes: how plain Coulomb friction between two
different solids fails to converge, beside the regularised runs' values (bimaterial study,
docs/bimaterial-study.md)."""

import math

from .common import colours, new_figure


def plot_growth(series, ylabel, title=None):
    """`series`: [(label, [(n_d, value), ...], style)] with style "line" (the runs under test,
    black solid lines) or "flat" (references, coloured dashed)."""
    fig, ax = new_figure(7.6, 4.4)
    solid = iter(["o-", "^-", "v-", "D-"])
    palette = colours(max(1, len(series)), "plasma")
    data = {}
    for colour, (label, points, style) in zip(palette, series):
        pts = sorted((float(n), float(v)) for n, v in points
                     if isinstance(v, (int, float)) and math.isfinite(v) and v > 0)
        if not pts:
            continue
        xs, ys = zip(*pts)
        if style == "line":
            ax.plot(xs, ys, next(solid, "o-"), color="black", lw=1.5, label=label)
        else:
            ax.plot(xs, ys, "s--", color=colour, lw=0.8, ms=5, label=label)
        data[label] = pts
    ax.set_xscale("log")
    ax.set_yscale("log")
    meshes = sorted({x for pts in data.values() for x, _ in pts})
    if meshes:
        ax.set_xticks(meshes, [f"{n:g}" for n in meshes])
        ax.set_xticks([], minor=True)
        ax.set_xlim(meshes[0] / 1.3, meshes[-1] * 1.3)
    ax.set_xlabel("n_d [nodes/m]")
    ax.set_ylabel(ylabel)
    ax.grid(True, which="both", color="0.9", lw=0.6)
    ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0)
    if title:
        ax.set_title(title)
    return fig, data
