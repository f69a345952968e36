"""The critical length against the event's highest frequency (paper Fig. 6, from runs): the
filter rule L_c(f) = (V* + |V|) / (2 pi f) * sqrt(1/0.98^2 - 1) (eq. 6 with A/A0 = 0.98,
docs/metrics.md "Spectral estimate"), and each run's (spectral_frequency,
spectral_critical_length); the L search's L_c and the paper's 1e-5 m as horizontal lines,
each with a star where it meets the rule: the frequency the event must hold for that L_c."""

import numpy as np

from .common import new_figure, ramp

ATTENUATION = 0.98


def critical_length(f, v_star, slip_velocity):
    """The largest L whose filter keeps A/A0 >= 0.98 at frequency f (eq. 6 solved for L)."""
    return (v_star + slip_velocity) / (2 * np.pi * np.asarray(f)) * np.sqrt(
        1 / ATTENUATION ** 2 - 1)


def frequency_of(L, v_star, slip_velocity):
    """The frequency at which the rule gives `L` (the inverse of critical_length)."""
    return float(critical_length(1.0, v_star, slip_velocity)) / L


def plot_critical_frequency(points, L_c=None, paper_L_c=1e-5, v_star=1e-4, title=None):
    """`points`: [(label, L, f, spectral L_c, |V|)] of each run."""
    fig, ax = new_figure(8.6, 4.6)
    data = {"points": points, "stars": {}}
    v = float(np.median([p[4] for p in points])) if points else 3e-3
    lines = [(L, name, colour, ls) for L, name, colour, ls in
             ((L_c, "L search: L_c", "C3", "-"), (paper_L_c, "paper: L_c ≈", "C1", "--")) if L]
    for L, _, _, _ in lines:
        data["stars"][L] = frequency_of(L, v_star, v)
    fs = [p[2] for p in points] + list(data["stars"].values())
    f = np.logspace(np.log10(min(fs) / 3), np.log10(max(fs) * 3), 200)
    top = 30 * max([p[3] for p in points] + [L for L, *_ in lines])
    ax.loglog(f, critical_length(f, v_star, v), color="grey",
              label=f"rule L_c(f): A/A0 = {ATTENUATION:g} at f, |V| = {v:.3g} m/s")
    ax.fill_between(f, critical_length(f, v_star, v), top, color="grey", alpha=0.12,
                    label="L > L_c(f): L acts on the event")
    for colour, (label, L, fr, lc, _) in zip(ramp(len(points), "viridis_r"), points):
        ax.plot([fr], [lc], "o", color=colour, label=label)
    for L, name, colour, ls in lines:
        ax.axhline(L, color=colour, ls=ls, lw=1.2, label=f"{name} {L:g} m")
        ax.plot([data["stars"][L]], [L], "*", ms=12, color=colour,
                label=f"  needs f = {data['stars'][L]:.3g} Hz")
    ax.set_ylim(min(L for L, *_ in lines + [(paper_L_c,)]) / 10, top)
    ax.set_xlabel("highest frequency of the event f [Hz] (dots: 99 % of the τ_s power at "
                  "x1 = 6 m)")
    ax.set_ylabel("L [m]")
    ax.set_title(title or "Critical length against the event's frequency")
    ax.legend(fontsize="x-small", loc="upper left", bbox_to_anchor=(1.01, 1.0))
    return fig, data
