"""Convergence with L (paper Fig. 4a, 4b): the mesh-converged run of each L, |V| against time
at x1 = 6 and 10 m and V_r against x1, darker for smaller L; the run at L_c drawn thick and
named, plain Coulomb (when given) in black."""

import matplotlib.pyplot as plt

from .common import clip_speed_axis, ramp
from .velocity import signal_window, velocity_at


def plot_length_convergence(results, L_c=None, coulomb=None, positions=(6.0, 10.0), title=None):
    """`results`: {L: Result}, one mesh-converged run per L; `coulomb`: a Result or None."""
    Ls = sorted(results, reverse=True)
    palette = ramp(len(Ls), "viridis_r")
    fig, axes = plt.subplots(1, len(positions) + 1, figsize=(4.2 * (len(positions) + 1), 3.8),
                             squeeze=False, constrained_layout=True)
    axes = list(axes[0])
    lines = [(L, results[L], colour) for L, colour in zip(Ls, palette)]
    if coulomb is not None:
        lines.append(("coulomb", coulomb, "black"))
    data = {"L": Ls, "L_c": L_c}

    def style(L, r):
        name = "Coulomb" if L == "coulomb" else f"L = {L:g} m, n_d = {float(r.n_d or 0):g}"
        at_lc = L_c is not None and L != "coulomb" and abs(L - L_c) <= 1e-9 * L_c
        return (name + (" (L_c)" if at_lc else ""), 2.2 if at_lc else 1.0,
                ":" if L == "coulomb" else "-")

    for ax, x in zip(axes, positions):
        samples = []
        for L, r, colour in lines:
            sample = velocity_at(r, x)
            if sample is None:
                continue
            _, t, v = sample
            samples.append((t, v))
            label, lw, ls = style(L, r)
            ax.plot(t, v * 1e3, color=colour, lw=lw, ls=ls, label=label)
        window = signal_window(samples) if samples else None
        if window:
            ax.set_xlim(*window)
        ax.set_title(f"(a) |V| at x1 = {x:g} m", fontsize="medium")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("|V| [mm/s]")
    ax = axes[-1]
    for L, r, colour in lines:
        label, lw, ls = style(L, r)
        ax.plot(r.front_x1, r.rupture_speed, color=colour, lw=lw, ls=ls, label=label)
    if lines:
        c_s, c_p = lines[0][1].wave_speeds()
        clip_speed_axis(ax, c_p)
        for c, name in ((c_s, "c_s"), (c_p, "c_p")):
            ax.axhline(c, color="grey", ls=":", lw=0.8)
    ax.set_title("(b) rupture speed (c_s, c_p dotted grey)", fontsize="medium")
    ax.set_xlabel("x1 [m]")
    ax.set_ylabel(r"$V_r$ [m/s]")
    ax.legend(fontsize="x-small")
    if title:
        fig.suptitle(title)
    return fig, data
