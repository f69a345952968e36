"""Mesh convergence at one L (paper Fig. 3a, 3b): |V| against time at x1 = 6 and 10 m and the
rupture speed V_r against x1, one line per n_d of the same L and method, darker for finer
meshes (the paper's colour ramp); the V_r axis stops a little above c_p."""

import matplotlib.pyplot as plt

from .common import ramp
from .velocity import velocity_and_speed_panels


def plot_mesh_convergence(results, positions=(6.0, 10.0), title=None):
    """`results`: runs of one L and method; drawn coarse (light) to fine (dark)."""
    runs = sorted(results, key=lambda r: float(r.n_d or 0))
    palette = ramp(len(runs))
    fig, axes = plt.subplots(1, len(positions) + 1, figsize=(4.2 * (len(positions) + 1), 3.6),
                             squeeze=False, constrained_layout=True)
    axes = list(axes[0])
    data = {"n_d": [float(r.n_d or 0) for r in runs], "velocity": {}, "speed": {}}
    curves = [(r, {"color": colour, "lw": 1.0, "label": f"n_d = {float(r.n_d or 0):g}"})
              for colour, r in zip(palette, runs)]
    for r, v in zip(runs, velocity_and_speed_panels(axes, curves, positions)):
        if v:
            data["velocity"][float(r.n_d or 0)] = v
        data["speed"][float(r.n_d or 0)] = r.rupture_speed
    ax = axes[-1]
    if runs:
        c_s, c_p = runs[0].wave_speeds()
        for c, name in ((c_s, "c_s"), (c_p, "c_p")):
            ax.text(ax.get_xlim()[0], c, f" {name}", va="bottom", fontsize="x-small", color="grey")
    ax.set_title("(b) rupture speed", fontsize="medium")
    ax.legend(fontsize="x-small")
    if title:
        fig.suptitle(title)
    return fig, data
