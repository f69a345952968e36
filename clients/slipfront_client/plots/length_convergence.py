"""Convergence with L (paper Fig. 4a, 4b): the mesh-converged run of each L, |V| against time
at x1 = 6 and 10 m and V_r against x1, darker for smaller L; the run at L_c drawn thick and
named, plain Coulomb (when given) in black."""

import matplotlib.pyplot as plt

from .common import ramp
from .velocity import velocity_and_speed_panels


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

    curves = []
    for L, r, colour in lines:
        label, lw, ls = style(L, r)
        curves.append((r, {"color": colour, "lw": lw, "ls": ls, "label": label}))
    velocity_and_speed_panels(axes, curves, positions)
    ax = axes[-1]
    ax.set_title("(b) rupture speed (c_s, c_p dotted grey)", fontsize="medium")
    ax.legend(fontsize="x-small")
    if title:
        fig.suptitle(title)
    return fig, data
