"""(c) Rupture speed V_r = dx1/dt_front against x1 (paper Fig. 2c, 3b, 4b), with the
shear and dilatational wave speeds c_s and c_p as horizontal lines (each solid's, named, at a
bimaterial interface) and the nucleation patch shaded: inside it the nucleation, not the
rupture, sets the front (the metrics `rupture_speed.max` and `.mean` leave it out;
docs/metrics.md)."""

import math

import numpy as np

from ..results import below_label, solid_wave_speeds
from .common import colours, method_style, new_figure


def nucleation_patch(spec):
    """(lo, hi) [m] of the x1 interval of the nucleation: the moving ellipse covers 0 to
    sqrt(a^2 + b^2) (solver/interface/nucleation.cpp), the overstressed patch [x1_min, x1_max];
    None when nucleation is disabled."""
    n = (spec or {}).get("nucleation") or {}
    if n.get("enabled", True) is False:
        return None
    if n.get("type") == "overstressed_patch":
        return float(n.get("x1_min", -0.5)), float(n.get("x1_max", 0.5))
    a, b = n.get("a", 0.6), n.get("b", 3.6)
    return 0.0, math.hypot(a, b)


def plot_speed(results, title=None, labels=None):
    """V_r against x1 of every run, named by `labels` (default: each run's label), in its
    method's line style and marker."""
    fig, ax = new_figure()
    data = {}
    patch = nucleation_patch(results[0].spec) if results else None
    if patch:
        ax.axvspan(*patch, color="tab:orange", alpha=0.15, lw=0,
                   label=f"nucleation patch ({patch[0]:.3g} to {patch[1]:.3g} m)")
        data["nucleation_patch"] = patch
    for colour, result, label in zip(colours(len(results)), results,
                                     labels or [r.label() for r in results]):
        ok = np.isfinite(result.rupture_speed)
        x, v = result.front_x1[ok], result.rupture_speed[ok]
        data[label] = {"x1": x, "rupture_speed": v}
        style = method_style(result.spec, result.metrics)
        ax.plot(x, v, color=colour, lw=1.2, ls=style["ls"], marker=style["marker"], ms=3,
                label=label)
    if results:
        c_s, c_p = results[0].wave_speeds()
        lines = [(c_s, r"$c_s$", "--"), (c_p, r"$c_p$", "-.")]
        if below_label(results[0].spec) == "bimaterial":  # each solid's speeds, named
            c_s2, c_p2 = solid_wave_speeds(results[0].spec["lower"])
            lines = [(c_s, r"$c_s$ upper", "--"), (c_p, r"$c_p$ upper", "-."),
                     (c_s2, r"$c_s$ lower", ":"), (c_p2, r"$c_p$ lower", (0, (8, 3, 1, 3)))]
            data["c_s_lower"], data["c_p_lower"] = c_s2, c_p2
        for v, name, style in lines:
            ax.axhline(v, color="grey", ls=style, lw=0.8)
            ax.text(ax.get_xlim()[1], v, name + " ", va="bottom", ha="right", color="grey")
        data["c_s"], data["c_p"] = c_s, c_p
        ax.set_ylim(0, 1.1 * max(v for v, _, _ in lines))
    ax.set_xlabel("x1 [m]")
    ax.set_ylabel(r"$V_r$ [m/s]")
    ax.set_title(title or "Rupture speed")
    if ax.get_legend_handles_labels()[0]:
        ax.legend(fontsize="small", loc="lower left")  # the arrest drops to the lower right
    return fig, data
