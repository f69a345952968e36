"""(c) Rupture speed V_r = dx1/dt_front against x1 (paper Fig. 2c, 3b, 4b), with the
shear and dilatational wave speeds c_s and c_p as horizontal lines."""

import numpy as np

from .common import colours, new_figure


def plot_speed(results, title=None):
    fig, ax = new_figure()
    data = {}
    for colour, result in zip(colours(len(results)), results):
        ok = np.isfinite(result.rupture_speed)
        x, v = result.front_x1[ok], result.rupture_speed[ok]
        data[result.label()] = {"x1": x, "rupture_speed": v}
        ax.plot(x, v, color=colour, lw=1.2, marker=".", ms=3, label=result.label())
    if results:
        c_s, c_p = results[0].wave_speeds()
        ax.axhline(c_s, color="grey", ls="--", lw=0.8)
        ax.axhline(c_p, color="grey", ls="-.", lw=0.8)
        ax.text(ax.get_xlim()[0], c_s, r" $c_s$", va="bottom", color="grey")
        ax.text(ax.get_xlim()[0], c_p, r" $c_p$", va="bottom", color="grey")
        data["c_s"], data["c_p"] = c_s, c_p
        ax.set_ylim(0, 1.1 * c_p)
    ax.set_xlabel("x1 [m]")
    ax.set_ylabel(r"$V_r$ [m/s]")
    ax.set_title(title or "Rupture speed")
    if ax.lines:
        ax.legend(fontsize="small")
    return fig, data
