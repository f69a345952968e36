"""(b) Slip velocity |V| against time at given positions x1 (paper Fig. 2b, 3a, 4a),
several runs overlaid, each labelled by what identifies it (results.run_label: method, friction
law and its scale parameter, n_d; or the labels given) and drawn in its method's line style
(FE solid, BI dashed). Each panel's time axis is zoomed to the signal: from a little before the first run's |V| exceeds 1 % of the panel's peak to a little
after the last run's falls below it (`zoom=False` shows the whole run)."""

import numpy as np
import matplotlib.pyplot as plt

from .common import colours, method_style

SIGNAL_FRACTION = 0.01
MAX_INSIDE_LEGEND = 4  # more runs than this: one legend beside the panels, not over them


def velocity_at(result, x1):
    """(node x1, time, |V|) at the interface node nearest to `x1`, or None outside."""
    if not (result.x1.min() - 1e-9 <= x1 <= result.x1.max() + 1e-9):
        return None
    node = int(np.argmin(np.abs(result.x1 - x1)))
    return float(result.x1[node]), result.time, np.abs(result.slip_velocity[:, node])


def signal_window(samples, fraction=SIGNAL_FRACTION, pad=0.15):
    """(t0, t1) covering every sample's |V| above `fraction` of the largest, padded by
    `pad` of the width on each side; None if there is no signal."""
    peak = max((float(np.nanmax(v)) for _, v in samples if v.size), default=0.0)
    if not peak > 0:
        return None
    starts, ends = [], []
    for t, v in samples:
        above = np.nonzero(v > fraction * peak)[0]
        if above.size:
            starts.append(t[above[0]])
            ends.append(t[above[-1]])
    t0, t1 = min(starts), max(ends)
    width = max(t1 - t0, 1e-9)
    first = min(float(t[0]) for t, _ in samples)
    last = max(float(t[-1]) for t, _ in samples)
    return max(first, t0 - pad * width), min(last, t1 + pad * width)


def plot_velocity(results, positions=None, title=None, zoom=True, labels=None):
    """One panel per position (None: the first run's own stations or probes,
    Result.positions); one line per run, named by `labels` (default: each run's label).
    Positions outside a run are skipped."""
    watched = dict(results[0].positions()) if results and positions is None else {}
    positions = list(watched) if positions is None else positions
    wide = len(results) > MAX_INSIDE_LEGEND
    fig, axes = plt.subplots(len(positions), 1,
                             figsize=(6.4 + (4.0 if wide else 0.0), 2.6 * len(positions) + 0.6),
                             squeeze=False, constrained_layout=True)
    data = {}
    palette = colours(len(results))
    for ax, x in zip(axes[:, 0], positions):
        samples = []
        for colour, result, label in zip(palette, results, labels or [r.label() for r in results]):
            sample = velocity_at(result, x)
            if sample is None:
                continue
            node_x, t, v = sample
            samples.append((t, v))
            data.setdefault(label, {})[x] = {"node_x1": node_x, "time": t, "abs_v": v}
            style = method_style(result.spec, result.metrics)
            ax.plot(t, v * 1e3, color=colour, lw=1.0, ls=style["ls"], label=label)
        ax.set_ylabel("|V| [mm/s]")
        window = signal_window(samples) if zoom and samples else None
        if window:
            ax.set_xlim(*window)
            data.setdefault("windows", {})[x] = window
        what = f" ({watched[x]})" if x in watched else ""
        ax.set_title(f"x1 = {x:g} m{what}" + (" (zoomed to the signal)" if window else ""),
                     fontsize="medium")
        ax.set_xlabel("t [s]")
        if ax.lines:
            if len(results) <= MAX_INSIDE_LEGEND:
                ax.legend(fontsize="small")
            elif ax is axes[0, 0]:  # many runs: one legend, beside the first panel
                ax.legend(fontsize="small", loc="upper left", bbox_to_anchor=(1.02, 1.0))
        else:
            ax.text(0.5, 0.5, "outside every run's domain", transform=ax.transAxes, ha="center")
    if title:
        fig.suptitle(title)
    return fig, data


def velocity_and_speed_panels(axes, curves, positions):
    """|V| against time at each of `positions` (one axis each, zoomed to the signal) and V_r
    against x1 on the last axis, the V_r axis cut a little above c_p with c_s and c_p dotted.
    `curves`: [(result, plot keyword arguments)]. Returns, per curve, {x1: |V| samples}."""
    from .common import clip_speed_axis
    drawn = [{} for _ in curves]
    for ax, x in zip(axes, positions):
        samples = []
        for k, (r, style) in enumerate(curves):
            sample = velocity_at(r, x)
            if sample is None:
                continue
            _, t, v = sample
            samples.append((t, v))
            drawn[k][x] = v
            ax.plot(t, v * 1e3, **style)
        window = signal_window(samples) if samples else None
        if window:
            ax.set_xlim(*window)
        ax.set_title(f"(a) |V| at x1 = {x:g} m", fontsize="medium")
        ax.set_xlabel("t [s]")
        ax.set_ylabel("|V| [mm/s]")
    ax = axes[-1]
    for r, style in curves:
        ax.plot(r.front_x1, r.rupture_speed, **style)
    if curves:
        c_s, c_p = curves[0][0].wave_speeds()
        clip_speed_axis(ax, c_p)
        for c in (c_s, c_p):
            ax.axhline(c, color="grey", ls=":", lw=0.8)
    ax.set_xlabel("x1 [m]")
    ax.set_ylabel(r"$V_r$ [m/s]")
    return drawn
