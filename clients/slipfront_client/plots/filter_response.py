"""(e) The friction filter's amplitude ratio against frequency (paper eq. 6, Fig. 5c):

    A/A0 = 1 / sqrt(1 + (2 pi f L / (V* + |V|))^2)

one curve per L, with dashed vertical lines at the highest eigenfrequency of each mesh,
f_max(n_d) = 1 / (pi dt_stable(n_d)). dt_stable is the run's `stable_dt` metric when a run
is given, otherwise dx / c_p with dx = 1/n_d (the paper's material: the solver's power
iteration gives the same to 5 digits).
"""

import numpy as np

from ..results import wave_speeds
from .common import colours, new_figure

PAPER_L = (1e-4, 5e-5, 1e-5, 5e-6)
PAPER_ND = (10, 20, 40, 80, 120)


def amplitude_ratio(f, L, v_star=1e-4, slip_velocity=0.0):
    """A/A0 of eq. 6 at frequencies `f` [Hz]."""
    return 1.0 / np.sqrt(1.0 + (2 * np.pi * np.asarray(f) * L / (v_star + abs(slip_velocity))) ** 2)


def stable_dt_estimate(n_d, c_p=None):
    """dx / c_p for the paper's material (or the given c_p)."""
    c_p = c_p or wave_speeds()[1]
    return 1.0 / (n_d * c_p)


def highest_frequency(stable_dt):
    return 1.0 / (np.pi * stable_dt)


def plot_filter(lengths=PAPER_L, meshes=None, v_star=1e-4, slip_velocity=3e-3,
                f_range=(1e-2, 1e3), title=None):
    """`meshes`: {n_d: stable_dt or None (estimated)}; default: the paper's n_d."""
    if meshes is None:
        meshes = {n: None for n in PAPER_ND}
    f = np.logspace(np.log10(f_range[0]), np.log10(f_range[1]), 400)
    fig, ax = new_figure()
    data = {"f": f, "curves": {}, "f_max": {}}
    for colour, L in zip(colours(len(lengths)), sorted(lengths, reverse=True)):
        ratio = amplitude_ratio(f, L, v_star, slip_velocity)
        data["curves"][L] = ratio
        ax.plot(f, ratio, color=colour, label=f"L = {L:g} m")
    for n_d, dt in sorted(meshes.items()):
        dt = dt or stable_dt_estimate(n_d)
        f_max = highest_frequency(dt)
        data["f_max"][n_d] = f_max
        ax.axvline(f_max, color="grey", ls="--", lw=0.8)
        ax.text(f_max, 1.02, rf"$\bar f_{{{n_d:g}}}$", rotation=90, ha="right", va="bottom", fontsize="x-small",
                color="grey")
    ax.set_xscale("log")
    ax.set_ylim(0, 1.12)
    ax.set_xlabel("f [Hz]")
    ax.set_ylabel("A/A0")
    ax.set_title(title or f"Friction filter, V* = {v_star:g} m/s, |V| = {slip_velocity:g} m/s")
    ax.legend(fontsize="small", loc="lower left")
    return fig, data
