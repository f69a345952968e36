"""(b) Slip velocity |V| against time at given positions x1 (paper Fig. 2b, 3a, 4a),
several runs overlaid and labelled by L and n_d."""

import numpy as np
import matplotlib.pyplot as plt

from .common import colours


def velocity_at(result, x1):
    """(node x1, time, |V|) at the interface node nearest to `x1`, or None outside."""
    if not (result.x1.min() - 1e-9 <= x1 <= result.x1.max() + 1e-9):
        return None
    node = int(np.argmin(np.abs(result.x1 - x1)))
    return float(result.x1[node]), result.time, np.abs(result.slip_velocity[:, node])


def plot_velocity(results, positions=(6.0, 10.0), title=None):
    """One panel per position; one line per run. Positions outside a run are skipped."""
    fig, axes = plt.subplots(len(positions), 1, figsize=(6.4, 2.6 * len(positions) + 0.6),
                             sharex=True, squeeze=False, constrained_layout=True)
    data = {}
    palette = colours(len(results))
    for ax, x in zip(axes[:, 0], positions):
        for colour, result in zip(palette, results):
            sample = velocity_at(result, x)
            if sample is None:
                continue
            node_x, t, v = sample
            data.setdefault(result.label(), {})[x] = {"node_x1": node_x, "time": t, "abs_v": v}
            ax.plot(t, v * 1e3, color=colour, lw=1.0, label=result.label())
        ax.set_ylabel("|V| [mm/s]")
        ax.set_title(f"x1 = {x:g} m", fontsize="medium")
        if ax.lines:
            ax.legend(fontsize="small")
        else:
            ax.text(0.5, 0.5, "outside every run's domain", transform=ax.transAxes, ha="center")
    axes[-1, 0].set_xlabel("t [s]")
    if title:
        fig.suptitle(title)
    return fig, data
