"""Slip rate against time at on-fault stations (docs/hdf5-layout.md "/stations": every time
step, so pulses shorter than the field's output interval are resolved), several runs
overlaid, one panel per station, each zoomed to the signal as in velocity.py."""

import matplotlib.pyplot as plt

from .common import colours
from .velocity import signal_window


def plot_station_rates(runs, positions, title=None, log_scale=False, t_max=None):
    """`runs`: [(label, Stations)], drawn in that order (the last on top). A station a run
    lacks is skipped in that run. `t_max` [s]: the end of the time axis instead of the
    signal's window."""
    fig, axes = plt.subplots(len(positions), 1, figsize=(6.4, 2.5 * len(positions) + 0.6),
                             squeeze=False, constrained_layout=True)
    data = {}
    palette = colours(len(runs))
    for ax, x in zip(axes[:, 0], positions):
        samples = []
        for colour, (label, st) in zip(palette, runs):
            found = [i for i, s in enumerate(st.x1) if abs(float(s) - x) < 1e-9]
            if not found:
                continue
            v = abs(st.slip_rate[:, found[0]])
            samples.append((st.time, v))
            data.setdefault(label, {})[x] = float(v.max()) if v.size else None
            ax.plot(st.time * 1e3, v, color=colour, lw=1.0, label=label)
        window = signal_window(samples) if samples else None
        if t_max is not None:
            window = (0.0, t_max)
        if window:
            ax.set_xlim(window[0] * 1e3, window[1] * 1e3)
        if log_scale:
            ax.set_yscale("log")
        ax.set_title(f"station x1 = {x:g} m", fontsize="medium")
        ax.set_xlabel("t [ms]")
        ax.set_ylabel("|V| [m/s]")
        if ax.lines:
            ax.legend(fontsize="small")
    if title:
        fig.suptitle(title)
    return fig, data
