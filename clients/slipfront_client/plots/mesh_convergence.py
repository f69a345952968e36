"""Mesh convergence at one L (paper Fig. 3a, 3b): |V| against time at x1 = 6 and 10 m and the
rupture speed V_r against x1, one line per n_d of the same L and method, darker for finer
meshes (the paper's colour ramp); the V_r axis stops a little above c_p."""

import matplotlib.pyplot as plt

from .common import clip_speed_axis, ramp
from .velocity import signal_window, velocity_at


def plot_mesh_convergence(results, positions=(6.0, 10.0), title=None):
    """`results`: runs of one L and method; drawn coarse (light) to fine (dark)."""
    runs = sorted(results, key=lambda r: float(r.n_d or 0))
    palette = ramp(len(runs))
    fig, axes = plt.subplots(1, len(positions) + 1, figsize=(4.2 * (len(positions) + 1), 3.6),
                             squeeze=False, constrained_layout=True)
    axes = list(axes[0])
    data = {"n_d": [float(r.n_d or 0) for r in runs], "velocity": {}, "speed": {}}
    for ax, x in zip(axes, positions):
        samples = []
        for colour, r in zip(palette, runs):
            sample = velocity_at(r, x)
            if sample is None:
                continue
            _, t, v = sample
            samples.append((t, v))
            data["velocity"].setdefault(float(r.n_d or 0), {})[x] = v
            ax.plot(t, v * 1e3, color=colour, lw=1.0, label=f"n_d = {float(r.n_d or 0):g}")
        window = signal_window(samples) if samples else None
        if window:
            ax.set_xlim(*window)
        ax.set_title(f"(a) |V| at x1 = {x:g} m", fontsize="medium")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("|V| [mm/s]")
    ax = axes[-1]
    for colour, r in zip(palette, runs):
        data["speed"][float(r.n_d or 0)] = r.rupture_speed
        ax.plot(r.front_x1, r.rupture_speed, color=colour, lw=1.0,
                label=f"n_d = {float(r.n_d or 0):g}")
    if runs:
        c_s, c_p = runs[0].wave_speeds()
        clip_speed_axis(ax, c_p)
        for c, name in ((c_s, "c_s"), (c_p, "c_p")):
            ax.axhline(c, color="grey", ls=":", lw=0.8)
            ax.text(ax.get_xlim()[0], c, f" {name}", va="bottom", fontsize="x-small", color="grey")
    ax.set_title("(b) rupture speed", fontsize="medium")
    ax.set_xlabel("x1 [m]")
    ax.set_ylabel(r"$V_r$ [m/s]")
    ax.legend(fontsize="x-small")
    if title:
        fig.suptitle(title)
    return fig, data
