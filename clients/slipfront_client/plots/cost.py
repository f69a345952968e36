"""(f) The speed–accuracy chart: wall time against error, one curve per L, each point
labelled with its n_d. Input rows: {L, n_d, wall_time_s, error} (error > 0; rows without
a positive error, such as a reference run, are left out)."""

import math

from ..errors import UsageError
from .common import colours, new_figure


def usable(row):
    try:
        return (float(row["error"]) > 0 and math.isfinite(float(row["error"])) and
                float(row["wall_time_s"]) > 0)
    except (KeyError, TypeError, ValueError):
        return False


def plot_cost(rows, title=None):
    rows = [r for r in rows if usable(r)]
    if not rows:
        raise UsageError("cost chart: no rows with a positive error and wall_time_s")
    by_L = {}
    for r in rows:
        by_L.setdefault(float(r["L"]), []).append(r)
    fig, ax = new_figure()
    data = {}
    for colour, L in zip(colours(len(by_L)), sorted(by_L, reverse=True)):
        runs = sorted(by_L[L], key=lambda r: float(r["n_d"]))
        err = [float(r["error"]) for r in runs]
        wall = [float(r["wall_time_s"]) for r in runs]
        data[L] = {"n_d": [float(r["n_d"]) for r in runs], "error": err, "wall_time_s": wall}
        ax.plot(err, wall, marker="o", color=colour, label=f"L = {L:g} m")
        for r, e, w in zip(runs, err, wall):
            ax.annotate(f"{float(r['n_d']):g}", (e, w), textcoords="offset points", xytext=(4, 3),
                        fontsize="x-small")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("relative error")
    ax.set_ylabel("wall time [s]")
    ax.set_title(title or "Speed and accuracy (labels: n_d)")
    ax.legend(fontsize="small")
    return fig, data
